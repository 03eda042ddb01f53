#pragma once
// Four joints' local transforms as structure of arrays (ozz-animation's SoaTransform): each component
// of the four joints side by side, so one SIMD instruction works on four joints (anim/simd_float4.h).
// A pose of n joints is ceil(n / 4) of these; the lanes past the last joint hold the identity.
#include <cstddef>
#include <span>

#include "anim/transform.h"

namespace anim {

inline constexpr std::size_t kSoaLanes = 4;

struct alignas(16) SoaFloat3 {
    float x[kSoaLanes], y[kSoaLanes], z[kSoaLanes];
};

struct alignas(16) SoaQuat {
    float x[kSoaLanes], y[kSoaLanes], z[kSoaLanes], w[kSoaLanes];
};

struct SoaTransform {
    SoaFloat3 translation;
    SoaQuat rotation;
    SoaFloat3 scale;
};

// Groups that hold `joints` joints.
constexpr std::size_t soaGroups(std::size_t joints) { return (joints + kSoaLanes - 1) / kSoaLanes; }

// One joint of a group, and back.
Transform soaLane(const SoaTransform& group, std::size_t lane);
void setSoaLane(SoaTransform& group, std::size_t lane, const Transform& t);

// A whole pose, each way: `soa` holds soaGroups(aos.size()) groups; padding lanes get the identity.
void toSoa(std::span<const Transform> aos, std::span<SoaTransform> soa);
void fromSoa(std::span<const SoaTransform> soa, std::span<Transform> aos);

}  // namespace anim
