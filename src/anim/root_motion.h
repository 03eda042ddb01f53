#pragma once
// Root motion: how far a clip carries its character over the ground, as a curve of its normalized
// phase. Clips here are authored in place (the hips stay over the origin), so the curve is measured
// from the feet (model/measure_root_motion.h): while a foot is planted, the body moves over it, so
// following this curve keeps planted feet still in the world.
#include <array>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace anim {

struct RootMotion {
    // Displacement in model space (x, z) over one whole cycle: samples[ROOT_MOTION_SAMPLES].
    glm::vec2 stride{0.0f};
    // Displacement from the cycle's start at phase i / ROOT_MOTION_SAMPLES; samples[0] is zero.
    std::array<glm::vec2, ROOT_MOTION_SAMPLES + 1> samples{};

    // The displacement at `phase` cycles from phase 0 (whole cycles add whole strides).
    glm::vec2 at(float phase) const;
    bool moves() const { return stride != glm::vec2(0.0f); }
};

// The curve's value at `phase` from a table of ROOT_MOTION_SAMPLES + 1 samples (linear between
// samples): shared by RootMotion::at and the clip library, and repeated in shaders/motion.glsl.inc.
glm::vec2 rootMotionAt(const glm::vec2* samples, float phase);

}  // namespace anim
