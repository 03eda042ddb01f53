#include "frame/memory_plan.h"

#include <algorithm>

#include "gpu/vulkan_context.h"
#include "render/driven_pass.h"
#include "render/ground_sunlight.h"
#include "render/impostor_prop_sets.h"
#include "render/mesh_raster.h"
#include "render/shadow_raster.h"
#include "render/terrain_buffer.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_capacity.h"

namespace frame {
namespace {

template <typename T>
std::uint64_t tableBytes(const std::vector<T>& table) {
    return std::max<std::uint64_t>(1, table.size()) * sizeof(T);  // empty tables upload one element
}

std::uint64_t textureBytes(const model::SkinnedModel& model) {
    const model::SkinnedModel::Texture& t = model.baseColorTexture;
    return t.width > 0 && t.height > 0 && !t.rgba.empty() ? std::uint64_t{t.width} * t.height * 4 : 0;
}

// Bind-pose vertices, indices of every LOD, texture coordinates, morph targets between levels, the
// model table, the material table, textures (a white one for untextured models): render::GeometryPool's buffers.
std::uint64_t geometryBytes(const crowd::Crowd& crowd) {
    std::uint64_t vertices = 0, indices = 0, textures = 4;
    for (const model::SkinnedModel* m : crowd.models()) {
        vertices += m->vertices.size();
        for (const model::SkinnedModel::Lod& lod : render::lodsOf(*m)) indices += lod.indices.size();
        textures += textureBytes(*m);
    }
    return vertices * (sizeof(gpu::SkinVertex) + sizeof(glm::vec2) + sizeof(gpu::LodMorphTarget)) + indices * sizeof(std::uint32_t) +
           crowd.models().size() * sizeof(gpu::ModelRecord) + sizeof(gpu::MaterialTable) + textures;
}

std::uint64_t libraryBytes(const anim::ClipLibrary& library) {
    return tableBytes(library.models()) + tableBytes(library.joints()) + tableBytes(library.clips()) +
           tableBytes(library.tracks()) + tableBytes(library.keyTimes()) + tableBytes(library.keyValues()) +
           tableBytes(library.rootSamples());
}

std::uint64_t methodBytes(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RecorderOptions& options) {
    const skin::SkinnedCapacity capacity = skin::skinnedCapacity(crowd, meshCapacityInEffect(options, crowd));
    return skin::estimateMethodBytes(options.method, crowd.size(), capacity.perFrame, capacity.fixed,
                                     skin::maxSkinTargetDimension(context, options.maxTargetDimension));
}

}  // namespace

std::uint64_t MemoryPlan::total() const {
    std::uint64_t sum = 0;
    for (const skin::MemoryItem& item : items) sum += item.bytes;
    return sum;
}

MemoryPlan planMemory(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RecorderOptions& options) {
    const std::uint64_t n = std::max(1u, crowd.size());
    const auto buckets = static_cast<std::uint32_t>(crowd.models().size() * LOD_COUNT);
    MemoryPlan plan;
    plan.items = {{"geometry pool (vertices, LOD indices, textures)", geometryBytes(crowd)},
                  {"character records and bone matrices",
                   crowd.size() * sizeof(gpu::CharacterRecord) +
                       render::planBones(context, crowd, skin::boneBlocksFor(options.method, options.animation),
                                         meshSlots(options, crowd))
                           .bytes()},
                  {"clip library (GPU animation)", libraryBytes(crowd.library())},
                  {"motion segments (GPU animation)", n * sizeof(gpu::MotionRecord)},
                  {"driven keys, counts and their uploads",
                   render::DrivenPass::bytesFor(crowd.size(), crowd.drivenKeysPerSlot(),
                                                static_cast<std::uint32_t>(crowd.models().size()), options.framesInFlight)},
                  {"terrain", render::TerrainBuffer::bytesFor(crowd, options.terrainSamples)},
                  {"culling lists and draw commands",
                   render::DrawLists::bytesFor(crowd.size(), buckets, meshCapacityInEffect(options, crowd),
                                               options.method == skin::Method::VertexShader)},
                  {"shadow map", std::uint64_t{options.shadowMapSize} * options.shadowMapSize * 2},  // 16-bit depth
                  {"ground sunlight (shadow map on the ground)", render::GroundSunlight::bytesFor(options.shadowMapSize)}};
    if (options.shadowRaster == render::ShadowRasterPath::Compute &&
        render::ShadowRaster::fits(context.properties.limits, options.shadowMapSize))
        plan.items.push_back({"shadow map depth (compute raster)", render::ShadowRaster::bytesFor(options.shadowMapSize)});
    if (options.events)
        plan.items.push_back({"event buffer, clip events, previous segments",
                              render::EventPass::bytesFor(crowd, options.eventCapacity, options.framesInFlight)});
    if (options.cull.impostors) {
        std::vector<gpu::ModelRecord> records(crowd.models().size());
        plan.items.push_back(
            {"impostor atlas", render::planImpostors(crowd.models(), records, render::impostorPropSets(crowd), options.impostorSettings).bytes()});
        const std::uint64_t draws = (n + IMPOSTOR_QUADS_PER_DRAW - 1) / IMPOSTOR_QUADS_PER_DRAW;
        plan.items.push_back({"impostor quad indices and draws",
                              std::uint64_t{IMPOSTOR_QUADS_PER_DRAW} * 6 * sizeof(std::uint32_t) +
                                  sizeof(gpu::ImpostorDrawsHeader) + draws * sizeof(gpu::DrawIndexedCommand)});
        // The compute rasterizer's list for the hardware path; its visibility buffers (8 bytes a pixel
        // and frame in flight) follow the viewport, which is not known here.
        if (options.raster != render::RasterMode::Hardware)
            plan.items.push_back({"visibility buffers and raster split", sizeof(gpu::ImpostorSplit) + n * 8});
    }
    // Small meshes in compute (methods that skin into a buffer): the list and split; the visibility
    // buffers follow the viewport, as above.
    const bool skinsIntoBuffer = options.method != skin::Method::VertexShader &&
                                 options.method != skin::Method::VertexShaderInstanced;
    const bool meshRaster = options.raster == render::RasterMode::Compute ||
                            (options.raster == render::RasterMode::Auto && options.meshRasterLimitPixels != 0.0f);
    if (meshRaster && skinsIntoBuffer) {
        std::uint32_t largest = 1;
        for (const model::SkinnedModel* model : crowd.models())
            largest = std::max(largest, static_cast<std::uint32_t>(render::lodsOf(*model).at(0).indices.size() / 3));
        const std::uint32_t drawCapacity = meshCapacityInEffect(options, crowd) > 0
                                               ? std::min(meshCapacityInEffect(options, crowd), crowd.size())
                                               : crowd.size();
        plan.items.push_back({"mesh visibility buffers and raster list",
                              render::meshRasterListBytes(render::meshRasterListCapacity(
                                  drawCapacity, render::meshRasterTriangleBits(largest)))});
    }
    plan.items.push_back({"skinning method (" + std::string(skin::methodName(options.method)) + ")",
                          methodBytes(context, crowd, options)});
    return plan;
}

}  // namespace frame
