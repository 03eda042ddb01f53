#pragma once
// Skinning job: model-space joint matrices to the 3x4 bone rows the GPU reads.
#include <span>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace anim {

// out[i] = rows of (world * model[i] * inverseBind[i]), the matrix that takes a bind-pose
// vertex straight to world space. Folding the character's placement into the bones means
// the GPU skins and places in one multiply.
void skinningMatrices(std::span<const glm::mat4> model, std::span<const glm::mat4> inverseBind,
                      const glm::mat4& world, std::span<gpu::BoneRows> out);

// The 3x4 rows of an affine matrix, and back.
gpu::BoneRows toRows(const glm::mat4& m);
glm::mat4 fromRows(const gpu::BoneRows& rows);

}  // namespace anim
