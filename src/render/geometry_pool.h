#pragma once
// Every model of a crowd on the GPU, pooled (niagara's shape): one bind-pose vertex buffer, one index
// buffer holding every model's every level of detail, one texture-coordinate buffer, the vertices'
// morph targets between levels, one material palette, and a model table (gpu::ModelRecord) that culling, skinning and drawing read.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu_types.h"
#include "model/skinned_model.h"
#include "render/material_textures.h"

namespace gpu { class VulkanContext; }

namespace render {

class GeometryPool {
public:
    // Models without levels of detail draw their full mesh at every level; a model without a pose
    // sphere gets one computed here. Throws gpu::Error when the palette or texture slots overflow.
    GeometryPool(const gpu::VulkanContext& context, std::span<const model::SkinnedModel* const> models);
    ~GeometryPool();
    GeometryPool(const GeometryPool&) = delete;
    GeometryPool& operator=(const GeometryPool&) = delete;

    const gpu::Buffer& bindVertices() const { return bindVertices_; }
    const gpu::Buffer& indices() const { return indices_; }
    const gpu::Buffer& textureCoordinates() const { return uvs_; }
    // gpu::LodMorphTarget per bind-pose vertex (model/lod_morph.h): read by skinning while a character
    // fades between mesh levels.
    const gpu::Buffer& lodMorphTargets() const { return lodMorphs_; }
    const gpu::Buffer& modelTable() const { return modelTable_; }
    // gpu::MaterialTable: every model's material colours, each model's indices offset by the materials
    // before it (materialBase), and texturedMaterials(), as the shaders read them.
    const gpu::Buffer& materials() const { return materials_; }
    const MaterialTextures& textures() const { return textures_; }
    // The model table as the GPU has it.
    const std::vector<gpu::ModelRecord>& models() const { return records_; }
    std::uint32_t modelCount() const { return static_cast<std::uint32_t>(records_.size()); }
    // Bit m of (x, y, z, w)[m / 32]: pooled material m is textured (as materials() holds it).
    glm::uvec4 texturedMaterials() const { return texturedMaterials_; }
    // The pooled material index of model m's material 0 (vertex material indices are offset by it).
    std::uint32_t materialBase(std::uint32_t model) const { return materialBases_[model]; }
    std::uint32_t maxJointCount() const { return maxJoints_; }
    VkDeviceSize bytes() const;

private:
    void release();

    const gpu::VulkanContext& context_;
    MaterialTextures textures_;
    std::vector<gpu::ModelRecord> records_;
    std::vector<glm::vec4> palette_;
    std::vector<std::uint32_t> materialBases_;
    glm::uvec4 texturedMaterials_{0u};
    std::uint32_t maxJoints_ = 0;
    gpu::Buffer bindVertices_;
    gpu::Buffer indices_;
    gpu::Buffer uvs_;
    gpu::Buffer lodMorphs_;
    gpu::Buffer modelTable_;
    gpu::Buffer materials_;
};

// The levels of a model as the pool draws them: its own, or the full mesh three times.
std::vector<model::SkinnedModel::Lod> lodsOf(const model::SkinnedModel& model);

}  // namespace render
