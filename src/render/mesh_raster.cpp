#include "render/mesh_raster.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>

#include "gpu/barriers.h"
#include "gpu/error.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/raster_mode.h"
#include "mesh_raster.comp.spv.h"
#include "mesh_raster_split.comp.spv.h"
#include "mesh_resolve.frag.spv.h"

namespace render {

namespace {
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
// Filled each frame, read back by the tests.
constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
constexpr std::uint32_t kSplitGroup = 64;  // mesh_raster_split.comp.glsl's local size

struct ResolvePush {
    glm::vec4 cameraPosition;
    glm::vec4 viewport;  // offset, extent
    glm::uvec4 idLayout;  // x: triangle bits
};
// The tiles' vertex shader (visibility_tiles.vert.glsl) reads the viewport there.
static_assert(offsetof(ResolvePush, viewport) == 16);

// The largest level 0 of the pool's models, in triangles.
std::uint32_t largestTriangleCount(const GeometryPool& pool) {
    std::uint32_t most = 1;
    for (const gpu::ModelRecord& model : pool.models()) most = std::max(most, model.lodIndexCount.x / 3);
    return most;
}
}  // namespace

std::uint32_t meshRasterTriangleBits(std::uint32_t largestTriangleCount) {
    return std::max(1u, static_cast<std::uint32_t>(std::bit_width(std::max(largestTriangleCount, 1u) - 1)));
}

std::uint32_t meshRasterListCapacity(std::uint32_t drawCapacity, std::uint32_t triangleBits) {
    // An id keeps 31 bits for (list place, triangle).
    return triangleBits >= 31 ? 0u : std::min(drawCapacity, 1u << (31 - triangleBits));
}

std::uint64_t meshRasterListBytes(std::uint32_t listCapacity) {
    return sizeof(gpu::MeshSplit) + std::uint64_t{std::max(listCapacity, 1u)} * 4;
}

MeshRaster::MeshRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                       const DrawLists& lists, VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target,
                       std::uint32_t framesInFlight, float limitPixels, std::uint32_t resolveTilePixels)
    : context_(context), pool_(pool), crowd_(crowd), lists_(lists), target_(target), limitPixels_(limitPixels),
      triangleBits_(meshRasterTriangleBits(largestTriangleCount(pool))), slots_(framesInFlight), sceneSetLayout_(sceneSetLayout) {
    requireComputeRaster(context);
    if (triangleBits_ > 24)
        throw gpu::Error("the compute rasterizer's ids hold up to 2^24 triangles a character; a model has more",
                         gpu::ErrorKind::Unsupported);
    listCapacity_ = meshRasterListCapacity(lists.drawCapacity(), triangleBits_);
    try {
        split_ = gpu::createBuffer(context, sizeof(gpu::MeshSplit), kUsage, gpu::MemoryUse::DeviceLocal,
                                   "mesh raster split");
        list_ = gpu::createBuffer(context, std::uint64_t{std::max(listCapacity_, 1u)} * 4, kUsage,
                                  gpu::MemoryUse::DeviceLocal, "meshes for the compute rasterizer");
        const gpu::BufferBinding splitBindings[] = {{kStorage, lists.draws().buffer}, {kStorage, lists.totals().buffer},
                                                    {kStorage, pool.modelTable().buffer},
                                                    {kStorage, crowd.characters().buffer},
                                                    {kStorage, split_.buffer},
                                                    {kStorage, list_.buffer}};
        splitSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, splitBindings);
        makePipelines(sceneSetLayout, framesInFlight, resolveTilePixels);
    } catch (...) {
        release();
        throw;
    }
}

MeshRaster::~MeshRaster() { release(); }

void MeshRaster::makePipelines(VkDescriptorSetLayout sceneSetLayout, std::uint32_t framesInFlight,
                               std::uint32_t resolveTilePixels) {
    // The slots' sets are made when the skinned vertices are known; layouts of the same shape, made here
    // with any buffer behind them (never bound), serve the pipeline layouts.
    const gpu::BufferBinding any{kStorage, split_.buffer};
    const gpu::BufferBinding rasterShape[6] = {any, any, any, any, any, any};
    const gpu::BufferBinding resolveShape[9] = {any, any, any, any, any, any, any, any, any};
    const gpu::DescriptorBundle rasterPrototype(context_, VK_SHADER_STAGE_COMPUTE_BIT, rasterShape);
    const gpu::DescriptorBundle resolvePrototype(context_, VK_SHADER_STAGE_FRAGMENT_BIT, resolveShape);

    const VkPushConstantRange computePush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::MeshRasterPush)};
    const VkDescriptorSetLayout splitSets[1] = {splitSet_->layout()};
    splitLayout_ = gpu::createPipelineLayout(context_, splitSets, {&computePush, 1});
    splitPipeline_ = gpu::createComputePipeline(context_, mesh_raster_split_comp_spv, splitLayout_, {});
    const VkDescriptorSetLayout rasterSets[1] = {rasterPrototype.layout()};
    rasterLayout_ = gpu::createPipelineLayout(context_, rasterSets, {&computePush, 1});
    rasterPipeline_ = gpu::createComputePipeline(context_, mesh_raster_comp_spv, rasterLayout_, {});

    const VkDescriptorSetLayout resolveSets[2] = {sceneSetLayout, resolvePrototype.layout()};
    const VkPushConstantRange resolvePush{kResolvePushStages, 0, sizeof(ResolvePush)};
    resolveLayout_ = gpu::createPipelineLayout(context_, resolveSets, {&resolvePush, 1});
    resolve_ = std::make_unique<VisibilityResolve>(context_, mesh_resolve_frag_spv, resolveLayout_, target_,
                                                   framesInFlight, resolveTilePixels);
}

void MeshRaster::release() {
    resolve_.reset();
    for (VkPipeline* pipeline : {&rasterPipeline_, &splitPipeline_}) {
        if (*pipeline) vkDestroyPipeline(context_.device, *pipeline, nullptr);
        *pipeline = VK_NULL_HANDLE;
    }
    for (VkPipelineLayout* layout : {&resolveLayout_, &rasterLayout_, &splitLayout_}) {
        if (*layout) vkDestroyPipelineLayout(context_.device, *layout, nullptr);
        *layout = VK_NULL_HANDLE;
    }
    for (Slot& slot : slots_) {
        slot.rasterSet.reset();
        slot.resolveSet.reset();
        gpu::destroyBuffer(context_, slot.visibility);
    }
    splitSet_.reset();
    gpu::destroyBuffer(context_, list_);
    gpu::destroyBuffer(context_, split_);
}

bool MeshRaster::canRead(const SkinnedVertices& vertices) const {
    const VkPhysicalDeviceLimits& limits = context_.properties.limits;
    return vertices.buffer && vertices.normalsOffset > 0 && vertices.normalsOffset <= limits.maxStorageBufferRange &&
           vertices.normalsOffset % limits.minStorageBufferOffsetAlignment == 0;
}

void MeshRaster::forgetVertices() {
    for (Slot& slot : slots_) slot.vertices = VK_NULL_HANDLE;
}

void MeshRaster::makeSets(std::uint32_t index, VkExtent2D extent, const SkinnedVertices& vertices) {
    Slot& slot = slots_[index];
    slot.rasterSet.reset();
    slot.resolveSet.reset();
    if (extent.width != slot.extent.width || extent.height != slot.extent.height || !slot.visibility.buffer) {
        gpu::destroyBuffer(context_, slot.visibility);
        slot.extent = extent;
        slot.visibility = gpu::createBuffer(context_, visibilityBytes(extent), kUsage,
                                            gpu::MemoryUse::DeviceLocal, "mesh visibility buffer");
    }
    const VkBuffer skinned = vertices.buffer->buffer;
    const VkDeviceSize stream = vertices.normalsOffset;
    const gpu::BufferBinding raster[] = {{kStorage, lists_.draws().buffer},  {kStorage, split_.buffer},
                                         {kStorage, list_.buffer},           {kStorage, pool_.indices().buffer},
                                         {kStorage, skinned, 0, stream},     {kStorage, slot.visibility.buffer}};
    slot.rasterSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, raster);
    const gpu::BufferBinding resolve[] = {{kStorage, lists_.draws().buffer},     {kStorage, list_.buffer},
                                          {kStorage, pool_.indices().buffer},    {kStorage, skinned, 0, stream},
                                          {kStorage, skinned, stream, stream},   {kStorage, pool_.modelTable().buffer},
                                          {kStorage, crowd_.characters().buffer}, {kStorage, slot.visibility.buffer},
                                          {kStorage, pool_.textureCoordinates().buffer}};
    slot.resolveSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_FRAGMENT_BIT, resolve);
    slot.vertices = skinned;
}

void MeshRaster::record(VkCommandBuffer cmd, std::uint32_t index, const SkinnedVertices& vertices,
                        const glm::mat4& viewProjection, const glm::vec3& eye, float pixelsPerUnit, VkExtent2D extent) {
    Slot& slot = slots_[index];
    if (extent.width != slot.extent.width || extent.height != slot.extent.height || slot.vertices != vertices.buffer->buffer)
        makeSets(index, extent, vertices);
    // The previous frame's resolve read the visibility buffer and the lists; the skinned vertices and
    // the colour list (culling's, a compute pass's or a copy's writes) are read here as storage.
    gpu::memoryBarrier(cmd,
                       {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_MEMORY_READ_BIT},
                       {VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    vkCmdFillBuffer(cmd, slot.visibility.buffer, 0, VK_WHOLE_SIZE, VISIBILITY_EMPTY_HIGH);
    vkCmdFillBuffer(cmd, split_.buffer, 0, VK_WHOLE_SIZE, 0u);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const std::uint32_t groups =
        std::clamp(listCapacity_, 1u, std::min(MESH_RASTER_MAX_WORKGROUPS, context_.properties.limits.maxComputeWorkGroupCount[0]));
    gpu::MeshRasterPush push{};
    push.viewProjection = viewProjection;
    push.camera = glm::vec4(eye, pixelsPerUnit);
    push.viewport = glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height), limitPixels_, 0.0f);
    push.limits = glm::uvec4(triangleBits_, listCapacity_, lists_.drawCapacity(), groups);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, splitPipeline_);
    const VkDescriptorSet splitSet = splitSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, splitLayout_, 0, 1, &splitSet, 0, nullptr);
    vkCmdPushConstants(cmd, splitLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, (lists_.drawCapacity() + kSplitGroup - 1) / kSplitGroup, 1, 1);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterPipeline_);
    const VkDescriptorSet rasterSet = slot.rasterSet->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterLayout_, 0, 1, &rasterSet, 0, nullptr);
    vkCmdPushConstants(cmd, rasterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, groups, 1, 1);
    // The colour draw reads the instance counts the split cleared; the tile scan and the resolve, the
    // visibility buffer.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
    resolve_->recordTiles(cmd, index, slot.visibility, slot.extent);
}

void MeshRaster::recordResolve(VkCommandBuffer cmd, std::uint32_t index, VkDescriptorSet sceneSet,
                               const glm::vec3& eye, const VkRect2D& viewport) const {
    const Slot& slot = slots_[index];
    if (!slot.resolveSet) return;  // never recorded: nothing to resolve
    resolve_->bind(cmd);
    const VkDescriptorSet sets[2] = {sceneSet, slot.resolveSet->set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, resolveLayout_, 0, 2, sets, 0, nullptr);
    const ResolvePush push{glm::vec4(eye, 1.0f),
                           glm::vec4(static_cast<float>(viewport.offset.x), static_cast<float>(viewport.offset.y),
                                     static_cast<float>(slot.extent.width), static_cast<float>(slot.extent.height)),
                           glm::uvec4(triangleBits_, 0u, 0u, 0u)};
    vkCmdPushConstants(cmd, resolveLayout_, kResolvePushStages, 0, sizeof push, &push);
    resolve_->draw(cmd, index);
}

std::uint64_t MeshRaster::bytes() const {
    std::uint64_t total = split_.size + list_.size;
    for (const Slot& slot : slots_) total += slot.visibility.size;
    return total + (resolve_ ? resolve_->bytes() : 0);
}

}  // namespace render
