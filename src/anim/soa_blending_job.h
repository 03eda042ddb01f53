#pragma once
// The blending job four joints at a time: anim::BlendingJob's lerps and short-arc nlerp on poses in
// structure of arrays.
#include <span>

#include "anim/soa_transform.h"

namespace anim {

struct SoaBlendingJob {
    std::span<const SoaTransform> from;
    std::span<const SoaTransform> to;
    float weight = 0.0f;  // of `to`: 0 gives `from`, 1 gives `to`
    std::span<SoaTransform> output;  // may alias `from` or `to`

    bool validate() const { return from.size() == to.size() && output.size() == from.size(); }
    void run() const;  // with simd::NativeFloat4
    template <class F>
    void runWith() const;  // F: simd::NativeFloat4 or simd::LaneFloat4
};

}  // namespace anim
