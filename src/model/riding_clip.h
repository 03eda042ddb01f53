#pragma once
// The rider's half of a mounted model's clip: a humanoid seated astride, its seat following the
// mount's gait (model/mounted_model.h joins it to each of the mount's clips).
#include <cstdint>
#include <optional>
#include <string>

#include "anim/clip.h"
#include "model/skinned_model.h"

namespace model {

// The rider's joints in the mounted skeleton, named as the built-in soldier's (hips, spine, chest,
// neck, head, clavicle_l, upperarm_l, forearm_l, hand_l, thigh_l, shin_l, foot_l and the _r side)
// after a prefix ("rider_").
struct RiderRig {
    std::uint32_t hips, spine, chest, neck, head;
    std::uint32_t clavicle[2], upperArm[2], forearm[2], hand[2];
    std::uint32_t thigh[2], shin[2], foot[2];
};

// The rig, or nothing when any of those joints is missing (a rider of another skeleton rides in its
// rest pose).
std::optional<RiderRig> findRiderRig(const anim::Skeleton& skeleton, const std::string& prefix);

// How the rider sits a gait: upright and deep in the saddle at a walk, or out of it, crouched
// forward over the withers at a gallop (a "two-point" seat).
enum class Seat { Upright, Forward };
// Forward for a clip named like a fast gait ("gallop", "canter", "run", "trot", any case), else upright.
Seat seatFor(const std::string& clipName);

// A clip of the mounted model that moves only the rider's joints, as long as `mountClip` and at the
// same phase: the rider's torso stays near upright in the world while the saddle pitches under it, and
// at a forward seat the legs take up the saddle's bob (the hips rise less than the saddle does). The
// saddle's motion is read from `mountClip` itself, so any mount with a saddle joint works.
anim::Clip bakeRidingClip(const SkinnedModel& mounted, const RiderRig& rider, std::uint32_t saddle,
                          const anim::Clip& mountClip);

}  // namespace model
