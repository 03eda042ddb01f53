#include "anim/root_motion.h"

#include <algorithm>
#include <cmath>

namespace anim {

glm::vec2 rootMotionAt(const glm::vec2* samples, float phase) {
    const float cycles = std::floor(phase);
    const float x = (phase - cycles) * static_cast<float>(ROOT_MOTION_SAMPLES);
    // A phase that is not finite gives x = NaN, which must not become an index: it reads sample 0 (and
    // returns NaN). The public API refuses such phases; this keeps a wild read out of the inner code.
    const int i = x > 0.0f ? std::min(static_cast<int>(x), ROOT_MOTION_SAMPLES - 1) : 0;
    const float f = x - static_cast<float>(i);
    const glm::vec2 within = samples[i] + (samples[i + 1] - samples[i]) * f;
    return samples[ROOT_MOTION_SAMPLES] * cycles + within;
}

glm::vec2 RootMotion::at(float phase) const { return rootMotionAt(samples.data(), phase); }

}  // namespace anim
