#pragma once
// The CPU reference every GPU method is tested against: linear blend skinning in double precision,
// written independently of the shaders (each bone transforms the vertex, then the results blend).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"
#include "model/lod_morph.h"
#include "model/skinned_model.h"

namespace skin {

struct CpuSkinnedVertex {
    glm::dvec3 position;
    glm::dvec3 normal;  // unit length; the bind normal where the bones collapse it (COLLAPSED_NORMAL_LENGTH2)
};

// Skins every vertex of `model` with one character's bones (bones[joint], as the GPU receives them).
std::vector<CpuSkinnedVertex> skinOnCpu(const model::SkinnedModel& model, std::span<const gpu::BoneRows> bones);

// One character's skinned vertices at `time` seconds into `clip`, standing at the origin (character
// transform = identity): the model's own space. A clip index past the last gives the rest pose. The
// CPU jobs only: sample, local to model (with the skeleton's root transform), skinning matrices, skin.
std::vector<CpuSkinnedVertex> poseOnCpu(const model::SkinnedModel& model, std::uint32_t clip, float time);

// A fade between mesh levels on the CPU (model/lod_morph.h): `skinned` (skinOnCpu's, every vertex)
// with each vertex from `firstMoving` on (the coarser level's vertex count) moved `share` of the way
// to its target, the blend of its target corners as skinned, and its normal turned with it.
std::vector<CpuSkinnedVertex> morphOnCpu(const std::vector<CpuSkinnedVertex>& skinned,
                                         const std::vector<model::LodMorphTarget>& targets, std::uint32_t firstMoving,
                                         double share);

}  // namespace skin
