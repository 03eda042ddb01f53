#include "model/riding_clip.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "model/looping_clip.h"

namespace model {
namespace {

// Index of the joint of this name, or -1.
std::int32_t jointIndex(const anim::Skeleton& skeleton, const std::string& name) {
    const auto it = std::find(skeleton.jointNames.begin(), skeleton.jointNames.end(), name);
    return it == skeleton.jointNames.end() ? -1 : static_cast<std::int32_t>(it - skeleton.jointNames.begin());
}

// What the rider feels of the gait at one phase: how far the saddle pitches nose-down (degrees) and
// how high it is above its mean height over the cycle (metres).
struct SaddleMotion {
    float pitch = 0.0f;
    float bob = 0.0f;
};

// The saddle's model-space matrix at `phase` of the mount's clip (the rider's joints still at rest).
glm::mat4 saddleAt(const SkinnedModel& mounted, std::uint32_t saddle, const anim::Clip& clip, float phase) {
    const anim::Skeleton& s = mounted.skeleton;
    std::vector<anim::Transform> locals(s.jointCount());
    std::vector<glm::mat4> global(s.jointCount());
    anim::sampleClip(clip, phase * clip.duration, s.restPose, locals);
    anim::localToModel(s.parents, locals, s.rootTransform, global);
    return global[saddle];
}

// Samples the saddle over the cycle once, so the pose function reads its motion by phase.
class SaddleTrack {
public:
    SaddleTrack(const SkinnedModel& mounted, std::uint32_t saddle, const anim::Clip& clip) {
        float meanHeight = 0.0f;
        for (int k = 0; k < kSamples; ++k) {
            const glm::mat4 m = saddleAt(mounted, saddle, clip, static_cast<float>(k) / kSamples);
            const glm::vec3 forward = glm::normalize(glm::vec3(m[2]));
            samples_[k].pitch = glm::degrees(std::atan2(-forward.y, std::hypot(forward.x, forward.z)));
            samples_[k].bob = m[3].y;
            meanHeight += m[3].y / kSamples;
        }
        for (SaddleMotion& s : samples_) s.bob -= meanHeight;
    }
    // Linear between the samples, wrapping round the loop.
    SaddleMotion at(float phase) const {
        const float x = wrapPhase(phase) * kSamples;
        const int k = static_cast<int>(x) % kSamples;
        const float f = x - std::floor(x);
        const SaddleMotion& a = samples_[k];
        const SaddleMotion& b = samples_[(k + 1) % kSamples];
        return {a.pitch + f * (b.pitch - a.pitch), a.bob + f * (b.bob - a.bob)};
    }

private:
    static constexpr int kSamples = 96;
    SaddleMotion samples_[kSamples];
};

// A seat's posture, in degrees and metres.
struct SeatShape {
    float thighForward, thighSpread;  // hip flexion, and the thighs opened round the barrel
    float knee, shinInward;           // knee flexion; the lower leg banked back in along the flank
    float heelDown;                   // ankle: heel below the toe in the stirrup
    float hipsFollow;                 // share of the saddle's pitch the pelvis follows (the rest the spine takes up)
    float spineLean, chestLean, neckLean, headLean;
    float rise, back;                 // hips out of the saddle (up) and behind the seat
    float absorb;                     // share of the saddle's bob the legs take up at a forward seat
    float upperArmForward, elbow;     // hands forward on the reins
};

// Deep and upright at a walk: the pelvis rocks with the horse, the torso stays upright above it.
constexpr SeatShape kUpright{.thighForward = 40.0f, .thighSpread = 38.0f, .knee = 70.0f, .shinInward = 34.0f,
                             .heelDown = 8.0f, .hipsFollow = 0.5f, .spineLean = 4.0f, .chestLean = 0.0f,
                             .neckLean = -2.0f, .headLean = -2.0f, .rise = 0.0f, .back = 0.0f, .absorb = 0.0f,
                             .upperArmForward = 22.0f, .elbow = 62.0f};
// Out of the saddle and over the withers at a gallop, the legs springing under the hips.
constexpr SeatShape kForward{.thighForward = 50.0f, .thighSpread = 36.0f, .knee = 85.0f, .shinInward = 46.0f,
                             .heelDown = 12.0f, .hipsFollow = 0.3f, .spineLean = 30.0f, .chestLean = 8.0f,
                             .neckLean = -18.0f, .headLean = -14.0f, .rise = 0.06f, .back = 0.05f, .absorb = 0.6f,
                             .upperArmForward = 38.0f, .elbow = 55.0f};

void poseRider(std::span<anim::Transform> pose, const RiderRig& r, const SeatShape& seat, const SaddleMotion& saddle) {
    auto turnBy = [&](std::uint32_t joint, const glm::quat& q) { pose[joint].rotation = pose[joint].rotation * q; };
    // The hips sit on the saddle and follow part of its pitch; the spine leans back by the rest, so the
    // torso keeps its lean in the world while the horse rocks under it.
    turnBy(r.hips, lean(-(1.0f - seat.hipsFollow) * saddle.pitch));
    pose[r.hips].translation += glm::vec3(0.0f, seat.rise - seat.absorb * saddle.bob, -seat.back);
    turnBy(r.spine, lean(seat.spineLean - seat.hipsFollow * saddle.pitch));
    turnBy(r.chest, lean(seat.chestLean));
    turnBy(r.neck, lean(seat.neckLean));
    turnBy(r.head, lean(seat.headLean));
    for (int side = 0; side < 2; ++side) {
        const float outward = side == 0 ? 1.0f : -1.0f;
        turnBy(r.thigh[side], bank(outward * seat.thighSpread) * swing(seat.thighForward));
        turnBy(r.shin[side], bank(-outward * seat.shinInward) * swing(-seat.knee));
        // The foot level in the stirrup, heel down: undo what the thigh and knee tipped it by.
        turnBy(r.foot[side], swing(seat.knee - seat.thighForward + seat.heelDown));
        // The reins give with the horse's head: the hands follow half the saddle's pitch.
        turnBy(r.upperArm[side], bank(-outward * 6.0f) * swing(seat.upperArmForward + 0.5f * saddle.pitch));
        turnBy(r.forearm[side], bank(outward * 10.0f) * swing(seat.elbow));
    }
}

}  // namespace

std::optional<RiderRig> findRiderRig(const anim::Skeleton& skeleton, const std::string& prefix) {
    bool complete = true;
    auto find = [&](const std::string& name) {
        const std::int32_t j = jointIndex(skeleton, prefix + name);
        complete = complete && j >= 0;
        return static_cast<std::uint32_t>(std::max(j, 0));
    };
    RiderRig r;
    r.hips = find("hips");
    r.spine = find("spine");
    r.chest = find("chest");
    r.neck = find("neck");
    r.head = find("head");
    for (int side = 0; side < 2; ++side) {
        const std::string suffix = side == 0 ? "_l" : "_r";
        r.clavicle[side] = find("clavicle" + suffix);
        r.upperArm[side] = find("upperarm" + suffix);
        r.forearm[side] = find("forearm" + suffix);
        r.hand[side] = find("hand" + suffix);
        r.thigh[side] = find("thigh" + suffix);
        r.shin[side] = find("shin" + suffix);
        r.foot[side] = find("foot" + suffix);
    }
    if (!complete) return std::nullopt;
    return r;
}

Seat seatFor(const std::string& clipName) {
    std::string lower = clipName;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* fast : {"gallop", "canter", "run", "trot"})
        if (lower.find(fast) != std::string::npos) return Seat::Forward;
    return Seat::Upright;
}

anim::Clip bakeRidingClip(const SkinnedModel& mounted, const RiderRig& rider, std::uint32_t saddle,
                          const anim::Clip& mountClip) {
    const SaddleTrack track(mounted, saddle, mountClip);
    const SeatShape& seat = seatFor(mountClip.name) == Seat::Forward ? kForward : kUpright;
    // As many keys as the built-in gaits have a cycle: the rider is sampled as finely as the horse.
    return bakeLoopingClip(mountClip.name, mountClip.duration, 24, mounted.skeleton,
                           [&](float phase, std::span<anim::Transform> pose) {
                               poseRider(pose, rider, seat, track.at(phase));
                           });
}

}  // namespace model
