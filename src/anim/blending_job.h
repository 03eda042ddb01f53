#pragma once
// Blending job: two poses of one skeleton mixed by a weight, joint by joint. Translations and scales
// are interpolated linearly, rotations normalized-linearly along the shorter arc (nlerp: the two
// poses of a crossfade are close, where nlerp and slerp agree and nlerp costs no trigonometry).
#include <span>

#include "anim/transform.h"

namespace anim {

struct BlendingJob {
    std::span<const Transform> from;
    std::span<const Transform> to;
    float weight = 0.0f;  // of `to`: 0 gives `from`, 1 gives `to`
    std::span<Transform> output;  // may alias `from` or `to`

    bool validate() const { return from.size() == to.size() && output.size() == from.size(); }
    void run() const;
};

// The blend of one pair of rotations, as the job and shaders/animation.glsl.inc compute it.
glm::quat nlerpShortest(const glm::quat& a, const glm::quat& b, float weight);

}  // namespace anim
