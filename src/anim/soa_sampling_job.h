#pragma once
// The sampling job four joints at a time (ozz's SoA sampling): the same pose as anim::SamplingJob, in
// structure of arrays. Each track's keys are still found one by one (tracks differ in key times; the
// same caller-owned cursors); the interpolation, the slerp's trigonometry and the normalization run on
// four joints per instruction. Cubic-spline tracks, rare, are sampled by the scalar job's code.
#include <cstdint>
#include <span>

#include "anim/clip_library.h"
#include "anim/soa_transform.h"

namespace anim {

struct SoaSamplingJob {
    const ClipLibrary* library = nullptr;
    std::uint32_t model = 0;
    std::uint32_t clip = 0;  // the model's own clip index
    float time = 0.0f;       // seconds; wrapped into the clip, so clips loop
    // Three per joint (translation, rotation, scale), kept by the caller between frames, as SamplingJob's.
    std::span<std::uint16_t> cursors;
    std::span<SoaTransform> output;  // soaGroups(joints) groups; padding lanes get the identity

    bool validate() const;
    // With the processor's backend (simd::NativeFloat4).
    void run() const;
    // With a given backend: F is simd::NativeFloat4 or simd::LaneFloat4 (the portable one, which tests run too).
    template <class F>
    void runWith() const;
};

}  // namespace anim
