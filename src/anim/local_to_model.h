#pragma once
// Hierarchy job: local joint transforms to model-space matrices.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "anim/transform.h"

namespace anim {

// out[i] = out[parents[i]] * locals[i], with rootTransform above the roots.
// Requires parents[i] < i (checked by the loaders), so one forward sweep suffices.
void localToModel(std::span<const std::int32_t> parents, std::span<const Transform> locals,
                  const glm::mat4& rootTransform, std::span<glm::mat4> out);

}  // namespace anim
