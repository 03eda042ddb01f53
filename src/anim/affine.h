#pragma once
// Affine transforms as three rows of a 3x4 matrix (gpu::BoneRows, the layout the GPU reads): the
// hierarchy and skinning jobs compose these instead of 4x4 matrices, 36 multiply-adds a product
// instead of 64, and shaders/animation.glsl.inc repeats the same operations.
#include <glm/glm.hpp>

#include "anim/transform.h"
#include "gpu_types.h"

namespace anim {

using Affine = gpu::BoneRows;

// a * b, as 4x4 matrices with a last row of (0, 0, 0, 1).
Affine compose(const Affine& a, const Affine& b);
// T * R * S of a joint's local transform; the rotation must be a unit quaternion.
Affine affineOf(const Transform& t);
// The placement of a character: translate to `position`, turn by `heading` about +y, scale uniformly.
Affine placementAffine(const glm::vec3& position, float heading, float scale);
// The same point transformed: rows dotted with (p, 1).
glm::vec3 transformPoint(const Affine& a, const glm::vec3& p);

}  // namespace anim
