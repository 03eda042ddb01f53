#pragma once
// The CPU reference every GPU method is tested against: linear blend skinning in double precision,
// written independently of the shaders (each bone transforms the vertex, then the results blend).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"
#include "model/skinned_model.h"

namespace skin {

struct CpuSkinnedVertex {
    glm::dvec3 position;
    glm::dvec3 normal;  // unit length; the bind normal where the bones collapse it (COLLAPSED_NORMAL_LENGTH2)
};

// Skins every vertex of `model` with one character's bones (bones[joint], as the GPU receives them).
std::vector<CpuSkinnedVertex> skinOnCpu(const model::SkinnedModel& model, std::span<const gpu::BoneRows> bones);

}  // namespace skin
