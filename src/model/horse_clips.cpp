#include "model/horse_clips.h"

#include <cmath>
#include <numbers>

#include "model/looping_clip.h"

namespace model {
namespace {

constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

// Legs in the order LH, LF, RH, RF (left hind, left fore, ...), each as its four joints from the body down.
struct Rig {
    std::uint32_t pelvis, spine, withers, neck, neckUpper, head, tail[3];
    std::uint32_t leg[4][4];
};
constexpr bool isFore(int leg) { return leg % 2 == 1; }

Rig findRig(const anim::Skeleton& s) {
    Rig r;
    r.pelvis = findJoint(s, "pelvis");
    r.spine = findJoint(s, "spine");
    r.withers = findJoint(s, "withers");
    r.neck = findJoint(s, "neck");
    r.neckUpper = findJoint(s, "neck_upper");
    r.head = findJoint(s, "head");
    for (int k = 0; k < 3; ++k) r.tail[k] = findJoint(s, "tail_" + std::to_string(k + 1));
    for (int side = 0; side < 2; ++side) {
        const std::string suffix = side == 0 ? "_l" : "_r";
        const std::uint32_t hind[4] = {findJoint(s, "thigh" + suffix), findJoint(s, "gaskin" + suffix),
                                       findJoint(s, "hind_cannon" + suffix), findJoint(s, "hind_pastern" + suffix)};
        const std::uint32_t fore[4] = {findJoint(s, "upperarm" + suffix), findJoint(s, "forearm" + suffix),
                                       findJoint(s, "front_cannon" + suffix), findJoint(s, "front_pastern" + suffix)};
        for (int k = 0; k < 4; ++k) {
            r.leg[2 * side][k] = hind[k];
            r.leg[2 * side + 1][k] = fore[k];
        }
    }
    return r;
}

// One leg's cycle, phase 0 at hoof strike: in stance the leg sweeps back with the hoof planted, in
// swing it folds (every joint zigzags) and reaches forward again.
struct LegCycle {
    float stance;       // fraction of the cycle the hoof is down
    float reachMean;    // upper joint swing about which the leg sweeps (degrees)
    float reach;        // sweep amplitude: forward at strike, back at lift-off
    float fold[3];      // flexion of the three lower joints at mid-swing
    float give[3];      // flexion of the same joints under the weight at mid-stance: it shortens the
                        // leg where the sweep would otherwise lift the body highest
};

// +1 at strike, -1 at lift-off; a cosine through stance, and back through the shorter swing.
float sweep(float q, float stance) {
    return q < stance ? std::cos(std::numbers::pi_v<float> * q / stance)
                      : -std::cos(std::numbers::pi_v<float> * (q - stance) / (1.0f - stance));
}

// 0 in stance, rising to 1 at mid-swing.
float lift(float q, float stance) {
    return q < stance ? 0.0f : std::sin(std::numbers::pi_v<float> * (q - stance) / (1.0f - stance));
}

void poseLeg(std::span<anim::Transform> pose, const std::uint32_t (&joints)[4], bool fore, float q,
             const LegCycle& c) {
    const float folded = lift(q, c.stance);
    const float weight = q < c.stance ? std::sin(std::numbers::pi_v<float> * q / c.stance) : 0.0f;
    pose[joints[0]].rotation = swing(c.reachMean + c.reach * sweep(q, c.stance));
    // Fore: the elbow lifts the forearm forward and the knee folds the cannon back. Hind: the stifle
    // takes the gaskin back and the hock brings the cannon forward. Both fold the pastern back.
    const float sign = fore ? 1.0f : -1.0f;
    // Under weight the fetlock sinks: the pastern tips the other way, towards the ground.
    pose[joints[1]].rotation = swing(sign * (c.fold[0] * folded + c.give[0] * weight));
    pose[joints[2]].rotation = swing(-sign * (c.fold[1] * folded + c.give[1] * weight));
    pose[joints[3]].rotation = swing(-c.fold[2] * folded + c.give[2] * weight);
}

struct Gait {
    LegCycle fore, hind;
    float footfall[4];   // phase of each leg's strike: LH, LF, RH, RF
    float pitch;         // body rocking nose-down (+) and up, once per stride
    float pitchAt;       // phase of the most nose-down moment
    float neckSwing;     // neck and head nodding against the body
    int nodsPerStride;
    float tailLift, tailSway;
    float flightAt, flightLift;  // suspension phase and height (gallop)
};

void poseGait(std::span<anim::Transform> pose, const Rig& r, float phase, const Gait& g) {
    for (int leg = 0; leg < 4; ++leg)
        poseLeg(pose, r.leg[leg], isFore(leg), wrapPhase(phase - g.footfall[leg]), isFore(leg) ? g.fore : g.hind);
    const float rock = std::cos(kTau * (phase - g.pitchAt));
    pose[r.pelvis].rotation = lean(g.pitch * rock) * bank(1.0f * wave(phase));
    pose[r.spine].rotation = turn(1.5f * wave(phase, 1.0f, 0.25f));
    // The neck swings like a pendulum against the body, so the head travels steadier than the withers.
    const float nod = std::cos(kTau * (phase * static_cast<float>(g.nodsPerStride) - g.pitchAt));
    pose[r.neck].rotation = lean(g.neckSwing * nod - 0.5f * g.pitch * rock);
    pose[r.neckUpper].rotation = lean(0.5f * g.neckSwing * nod);
    pose[r.head].rotation = lean(-0.8f * g.neckSwing * nod);
    pose[r.tail[0]].rotation = swing(-g.tailLift) * bank(g.tailSway * wave(phase));
    pose[r.tail[1]].rotation = swing(-0.5f * g.tailLift) * bank(g.tailSway * wave(phase, 1.0f, -0.1f));
    pose[r.tail[2]].rotation = swing(0.3f * g.tailLift) * bank(g.tailSway * wave(phase, 1.0f, -0.2f));
}

anim::Clip bakeGait(const SkinnedModel& horse, const Rig& r, std::string name, float duration, const Gait& g) {
    auto pose = [&](float phase, std::span<anim::Transform> locals) {
        poseGait(locals, r, phase, g);
        // The lowest hoof meets the ground; in the gallop's suspension the whole horse rises off it.
        const float lift = g.flightLift * bump(phase, g.flightAt, 0.07f);
        locals[r.pelvis].translation.y += lift - lowestSkinnedY(horse, locals);
    };
    return bakeLoopingClip(std::move(name), duration, 24, horse.skeleton, pose);
}

// A four-beat lateral walk: left hind, left fore, right hind, right fore, evenly spaced, with
// two or three hooves down at any time.
anim::Clip walkClip(const SkinnedModel& horse, const Rig& r) {
    const Gait walk{
        .fore = {.stance = 0.62f, .reachMean = 2.0f, .reach = 13.0f,
                 .fold = {15.0f, 60.0f, 45.0f}, .give = {0.0f, 0.0f, 8.0f}},
        .hind = {.stance = 0.62f, .reachMean = 0.0f, .reach = 13.0f,
                 .fold = {30.0f, 55.0f, 50.0f}, .give = {0.0f, 0.0f, 8.0f}},
        .footfall = {0.0f, 0.25f, 0.5f, 0.75f},
        .pitch = 1.0f, .pitchAt = 0.25f, .neckSwing = 3.0f, .nodsPerStride = 2,
        .tailLift = 0.0f, .tailSway = 6.0f, .flightAt = 0.0f, .flightLift = 0.0f};
    return bakeGait(horse, r, "walk", 1.1f, walk);
}

// A transverse gallop on the right lead: the hind pair lands close together, then the fore pair,
// then all four hooves leave the ground; the body rocks up on the hinds and down on the fores.
anim::Clip gallopClip(const SkinnedModel& horse, const Rig& r) {
    const Gait gallop{
        .fore = {.stance = 0.32f, .reachMean = 4.0f, .reach = 26.0f,
                 .fold = {35.0f, 110.0f, 70.0f}, .give = {0.0f, 0.0f, 30.0f}},
        .hind = {.stance = 0.34f, .reachMean = 4.0f, .reach = 24.0f,
                 .fold = {45.0f, 60.0f, 60.0f}, .give = {5.0f, 12.0f, 25.0f}},
        .footfall = {0.0f, 0.34f, 0.1f, 0.44f},
        .pitch = 6.0f, .pitchAt = 0.55f, .neckSwing = 7.0f, .nodsPerStride = 1,
        .tailLift = 25.0f, .tailSway = 4.0f, .flightAt = 0.88f, .flightLift = 0.08f};
    return bakeGait(horse, r, "gallop", 0.6f, gallop);
}

}  // namespace

std::vector<anim::Clip> makeHorseClips(const SkinnedModel& horse) {
    const Rig rig = findRig(horse.skeleton);
    return {walkClip(horse, rig), gallopClip(horse, rig)};
}

}  // namespace model
