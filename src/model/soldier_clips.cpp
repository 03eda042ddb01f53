#include "model/soldier_clips.h"

#include <cmath>
#include <numbers>

#include "model/looping_clip.h"

namespace model {
namespace {

constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

struct Rig {
    std::uint32_t hips, spine, chest, neck, head;
    std::uint32_t clavicle[2], upperArm[2], forearm[2], hand[2];
    std::uint32_t thigh[2], shin[2], foot[2], toe[2];
};

Rig findRig(const anim::Skeleton& s) {
    Rig r;
    r.hips = findJoint(s, "hips");
    r.spine = findJoint(s, "spine");
    r.chest = findJoint(s, "chest");
    r.neck = findJoint(s, "neck");
    r.head = findJoint(s, "head");
    for (int side = 0; side < 2; ++side) {
        const std::string suffix = side == 0 ? "_l" : "_r";
        r.clavicle[side] = findJoint(s, "clavicle" + suffix);
        r.upperArm[side] = findJoint(s, "upperarm" + suffix);
        r.forearm[side] = findJoint(s, "forearm" + suffix);
        r.hand[side] = findJoint(s, "hand" + suffix);
        r.thigh[side] = findJoint(s, "thigh" + suffix);
        r.shin[side] = findJoint(s, "shin" + suffix);
        r.foot[side] = findJoint(s, "foot" + suffix);
        r.toe[side] = findJoint(s, "toe" + suffix);
    }
    return r;
}

// How a gait bends the joints of one leg cycle (phase 0 = heel strike), in degrees.
struct LegCycle {
    float thighMean, thighSwing;       // hip flexion: mean and amplitude (forward at heel strike)
    float kneeStance, kneeStanceAt;    // knee flexion as the leg takes the weight, and when
    float kneeSwing;                   // knee flexion peak in swing
    float kneeSwingAt, kneeSwingWidth; // phase and spread of the swing knee peak
    float pushOff;                     // ankle plantar flexion at toe-off
    float toeOffAt;
};

struct ArmCycle {
    float swing;      // shoulder amplitude, opposite to the leg on the same side
    float elbowMean;  // forearm flexion
    float elbowSwing; // extra flexion as the arm comes forward
    float spread;     // arms held a little out from the body
};

void poseLeg(std::span<anim::Transform> pose, const Rig& r, int side, float q, const LegCycle& c) {
    pose[r.thigh[side]].rotation = swing(c.thighMean + c.thighSwing * std::cos(kTau * q));
    const float knee = 4.0f + c.kneeStance * bump(q, c.kneeStanceAt, 0.09f) +
                       c.kneeSwing * bump(q, c.kneeSwingAt, c.kneeSwingWidth);
    pose[r.shin[side]].rotation = swing(-knee);
    const float ankle = 6.0f * bump(q, 0.0f, 0.05f) - c.pushOff * bump(q, c.toeOffAt, 0.07f) +
                        8.0f * bump(q, c.kneeSwingAt + 0.08f, 0.1f);
    pose[r.foot[side]].rotation = swing(ankle);
    // The toes stay flat on the ground while the heel rises into toe-off.
    pose[r.toe[side]].rotation = swing(0.8f * c.pushOff * bump(q, c.toeOffAt - 0.03f, 0.06f));
}

void poseArm(std::span<anim::Transform> pose, const Rig& r, int side, float q, const ArmCycle& c) {
    const float outward = side == 0 ? 1.0f : -1.0f;
    const float forward = -std::cos(kTau * q);  // +1 when the same-side leg is furthest back
    pose[r.upperArm[side]].rotation = bank(outward * c.spread) * swing(c.swing * forward);
    pose[r.forearm[side]].rotation = swing(c.elbowMean + c.elbowSwing * (0.5f + 0.5f * forward));
}

struct Gait {
    LegCycle leg;
    ArmCycle arm;
    float lean;        // forward lean of the spine
    float hipTurn;     // pelvis yaw with the legs, shoulders counter-turn
    float hipRoll;     // pelvis drops on the swing side
    float flightLift;  // extra height between foot contacts (running)
};

void poseGait(std::span<anim::Transform> pose, const Rig& r, float phase, const Gait& g) {
    for (int side = 0; side < 2; ++side) {
        const float q = wrapPhase(phase + 0.5f * static_cast<float>(side));
        poseLeg(pose, r, side, q, g.leg);
        poseArm(pose, r, side, q, g.arm);
    }
    // The pelvis turns the left hip forward as the left leg reaches forward.
    pose[r.hips].rotation = turn(-g.hipTurn * std::cos(kTau * phase)) * bank(g.hipRoll * std::sin(kTau * phase));
    pose[r.spine].rotation = lean(g.lean) * turn(0.5f * g.hipTurn * std::cos(kTau * phase));
    pose[r.chest].rotation = turn(1.2f * g.hipTurn * std::cos(kTau * phase)) * lean(0.3f * g.lean);
    // The head stays level and looking ahead while the body leans and turns under it.
    pose[r.neck].rotation = lean(-0.6f * g.lean);
    pose[r.head].rotation = lean(-0.7f * g.lean) * turn(-0.7f * g.hipTurn * std::cos(kTau * phase));
}

// Sits the pose on the ground: the lowest vertex at y = 0, plus any lift in the air.
void plantOnGround(const SkinnedModel& soldier, const Rig& r, std::span<anim::Transform> pose, float lift) {
    pose[r.hips].translation.y += lift - lowestSkinnedY(soldier, pose);
}

anim::Clip walkClip(const SkinnedModel& soldier, const Rig& r) {
    const Gait walk{
        .leg = {.thighMean = 4.0f, .thighSwing = 21.0f, .kneeStance = 12.0f, .kneeStanceAt = 0.14f,
                .kneeSwing = 58.0f, .kneeSwingAt = 0.72f, .kneeSwingWidth = 0.12f, .pushOff = 16.0f, .toeOffAt = 0.58f},
        .arm = {.swing = 16.0f, .elbowMean = 10.0f, .elbowSwing = 14.0f, .spread = 4.0f},
        .lean = 3.0f, .hipTurn = 5.0f, .hipRoll = 3.0f, .flightLift = 0.0f};
    return bakeLoopingClip("walk", 1.1f, 24, soldier.skeleton, [&](float phase, std::span<anim::Transform> pose) {
        poseGait(pose, r, phase, walk);
        plantOnGround(soldier, r, pose, 0.0f);
    });
}

anim::Clip runClip(const SkinnedModel& soldier, const Rig& r) {
    const Gait run{
        .leg = {.thighMean = 12.0f, .thighSwing = 26.0f, .kneeStance = 35.0f, .kneeStanceAt = 0.17f,
                .kneeSwing = 100.0f, .kneeSwingAt = 0.62f, .kneeSwingWidth = 0.15f,
                .pushOff = 25.0f, .toeOffAt = 0.38f},
        .arm = {.swing = 30.0f, .elbowMean = 75.0f, .elbowSwing = 20.0f, .spread = 8.0f},
        .lean = 9.0f, .hipTurn = 7.0f, .hipRoll = 3.0f, .flightLift = 0.05f};
    return bakeLoopingClip("run", 0.7f, 24, soldier.skeleton, [&](float phase, std::span<anim::Transform> pose) {
        poseGait(pose, r, phase, run);
        // Both feet leave the ground between one toe-off and the other heel strike.
        const float flight = bump(phase, 0.44f, 0.05f) + bump(phase, 0.94f, 0.05f);
        plantOnGround(soldier, r, pose, run.flightLift * flight);
    });
}

// The right arm's angles at shoulder arms (degrees): upper arm forward and out, elbow bent.
constexpr float kShoulderArmsUpperArm = 12.0f;
constexpr float kShoulderArmsOut = 8.0f;
constexpr float kShoulderArmsElbow = 118.0f;

anim::Clip idleClip(const SkinnedModel& soldier, const Rig& r) {
    return bakeLoopingClip("idle", 3.0f, 32, soldier.skeleton, [&](float phase, std::span<anim::Transform> pose) {
        // One slow breath per loop lifts the chest and shoulders.
        const float breath = wave(phase);
        pose[r.chest].rotation = lean(-1.5f * breath);
        for (int side = 0; side < 2; ++side) {
            const float outward = side == 0 ? 1.0f : -1.0f;
            pose[r.clavicle[side]].rotation = bank(outward * -1.5f * breath);
            pose[r.upperArm[side]].rotation = bank(outward * 3.0f) * swing(1.5f * wave(phase, 1.0f, 0.2f));
            pose[r.forearm[side]].rotation = swing(8.0f);
        }
        // Shoulder arms: the right forearm raised, the hand before the shoulder, so that the rifle it
        // carries in the walk (muzzle forward) stands sloped up and back against the shoulder.
        pose[r.upperArm[1]].rotation = bank(-kShoulderArmsOut) * swing(kShoulderArmsUpperArm + 1.0f * wave(phase, 1.0f, 0.2f));
        pose[r.forearm[1]].rotation = swing(kShoulderArmsElbow);
        // Weight shifts from foot to foot: the pelvis slides and tilts, the legs lean to keep the feet put.
        const float shift = wave(phase, 1.0f, 0.25f);
        pose[r.hips].translation.x += 0.02f * shift;
        pose[r.hips].rotation = bank(-2.0f * shift);
        const float legLean = glm::degrees(std::atan2(0.02f * shift, 0.9f));
        for (int side = 0; side < 2; ++side) {
            pose[r.thigh[side]].rotation = bank(2.0f * shift - legLean);
            pose[r.foot[side]].rotation = bank(legLean);
        }
        pose[r.spine].rotation = bank(1.5f * shift);
        pose[r.head].rotation = turn(5.0f * wave(phase, 1.0f, 0.6f)) * lean(2.0f * wave(phase, 2.0f));
        plantOnGround(soldier, r, pose, 0.0f);
    });
}

}  // namespace

std::vector<anim::Clip> makeSoldierClips(const SkinnedModel& soldier) {
    const Rig rig = findRig(soldier.skeleton);
    return {idleClip(soldier, rig), walkClip(soldier, rig), runClip(soldier, rig)};
}

}  // namespace model
