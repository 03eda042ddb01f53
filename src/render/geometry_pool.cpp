#include "render/geometry_pool.h"

#include <algorithm>
#include <string>

#include "crowd/pose_bounds.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "model/lod_morph.h"

namespace render {

std::vector<model::SkinnedModel::Lod> lodsOf(const model::SkinnedModel& model) {
    std::vector<model::SkinnedModel::Lod> lods = model.lods;
    const model::SkinnedModel::Lod full{model.indices, static_cast<std::uint32_t>(model.vertices.size())};
    if (lods.empty()) lods.push_back(full);
    while (lods.size() < LOD_COUNT) lods.push_back(lods.back());
    lods.resize(LOD_COUNT);
    return lods;
}

namespace {

// What the pool uploads, gathered on the CPU first.
struct PoolData {
    std::vector<gpu::SkinVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<glm::vec2> uvs;
    std::vector<gpu::LodMorphTarget> morphs;
};

void appendModel(const model::SkinnedModel& model, std::uint32_t materialBase, PoolData& data,
                 gpu::ModelRecord& record) {
    record.info.x = static_cast<std::uint32_t>(data.vertices.size());
    record.info.y = static_cast<std::uint32_t>(model.skeleton.jointCount());
    for (gpu::SkinVertex v : model.vertices) {
        v.normal.w += static_cast<float>(materialBase);  // material indices into the pooled palette
        data.vertices.push_back(v);
    }
    std::vector<glm::vec2> uvs = model.uvs;
    uvs.resize(model.vertices.size(), glm::vec2(0.0f));
    data.uvs.insert(data.uvs.end(), uvs.begin(), uvs.end());
    const std::vector<model::SkinnedModel::Lod> lods = lodsOf(model);
    // Corners stay model-relative, as indices do: the shaders add the model's first vertex.
    for (const model::LodMorphTarget& target : model::lodMorphTargets(model, lods))
        data.morphs.push_back({model::packLodMorphTarget(target)});
    for (int l = 0; l < LOD_COUNT; ++l) {
        // Indices stay model-relative: draws add the model's first vertex (bind pose) or the
        // character's first skinned vertex as vertexOffset.
        record.lodFirstIndex[l] = static_cast<std::uint32_t>(data.indices.size());
        record.lodIndexCount[l] = static_cast<std::uint32_t>(lods[l].indices.size());
        record.lodVertexCount[l] = lods[l].vertexCount;
        data.indices.insert(data.indices.end(), lods[l].indices.begin(), lods[l].indices.end());
    }
    record.sphere = model.poseSphere.w > 0.0f ? model.poseSphere : crowd::computePoseSphere(model);
}

}  // namespace

GeometryPool::GeometryPool(const gpu::VulkanContext& context, std::span<const model::SkinnedModel* const> models)
    : context_(context), textures_(context, models) {
    PoolData data;
    for (std::uint32_t m = 0; m < models.size(); ++m) {
        const model::SkinnedModel& model = *models[m];
        const auto base = static_cast<std::uint32_t>(palette_.size());
        if (base + model.materialColors.size() > MAX_MATERIALS)
            throw gpu::Error("a crowd's models may have at most " + std::to_string(MAX_MATERIALS) +
                             " materials together (" + model.name + " brings the total to " +
                             std::to_string(base + model.materialColors.size()) + ")");
        materialBases_.push_back(base);
        palette_.insert(palette_.end(), model.materialColors.begin(), model.materialColors.end());
        for (std::uint32_t i = 0; i < model.materialColors.size() && i < 32; ++i)
            if ((model.texturedMaterials >> i) & 1u) texturedMaterials_[(base + i) / 32] |= 1u << ((base + i) % 32);
        gpu::ModelRecord record{};
        appendModel(model, base, data, record);
        record.info.z = textures_.slotOf(m);
        records_.push_back(record);
        maxJoints_ = std::max(maxJoints_, record.info.y);
    }
    try {
        constexpr VkBufferUsageFlags vertexUse = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        bindVertices_ = gpu::createBufferWithData(context, std::as_bytes(std::span(data.vertices)), vertexUse,
                                                  "bind-pose vertices");
        indices_ = gpu::createBufferWithData(context, std::as_bytes(std::span(data.indices)),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "indices");
        uvs_ = gpu::createBufferWithData(context, std::as_bytes(std::span(data.uvs)),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "texture coordinates");
        lodMorphs_ = gpu::createBufferWithData(context, std::as_bytes(std::span(data.morphs)),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "level-of-detail morph targets");
        modelTable_ = gpu::createBufferWithData(context, std::as_bytes(std::span(records_)),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "model table");
        gpu::MaterialTable table{};
        table.textured = texturedMaterials_;
        std::copy(palette_.begin(), palette_.end(), table.colors);
        materials_ = gpu::createBufferWithData(context, std::as_bytes(std::span(&table, 1)),
                                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "material table");
    } catch (...) {
        release();
        throw;
    }
}

GeometryPool::~GeometryPool() { release(); }

void GeometryPool::release() {
    gpu::destroyBuffer(context_, materials_);
    gpu::destroyBuffer(context_, modelTable_);
    gpu::destroyBuffer(context_, lodMorphs_);
    gpu::destroyBuffer(context_, uvs_);
    gpu::destroyBuffer(context_, indices_);
    gpu::destroyBuffer(context_, bindVertices_);
}

VkDeviceSize GeometryPool::bytes() const {
    return bindVertices_.size + indices_.size + uvs_.size + lodMorphs_.size + modelTable_.size + materials_.size +
           textures_.bytes();
}

}  // namespace render
