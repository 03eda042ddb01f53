#include "render/shadow_raster.h"

#include <algorithm>

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "gpu_types.h"
#include "render/character_draw.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/shadow_cascades.h"
#include "render/shadow_map.h"
#include "shadow_pack.comp.spv.h"
#include "shadow_raster.comp.spv.h"

namespace render {
namespace {

struct RasterPush {
    ShadowRasterLight light;
    glm::uvec4 sizes;
};
static_assert(sizeof(RasterPush) == 128, "the least push-constant space Vulkan guarantees");

constexpr std::uint32_t kMostGroupsPerRow = 65535;  // the least maxComputeWorkGroupCount[0] Vulkan allows
constexpr std::uint32_t kFarDepthBits = 0x3F800000u;  // 1.0f: the cleared map

constexpr gpu::Access kComputeReadWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr gpu::Access kComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
constexpr gpu::Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr gpu::Access kCopyRead{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};

constexpr std::uint32_t kPackGroupSize = 256;  // shadow_pack.comp.glsl's local_size_x
// The large triangles' records (shadow_raster.comp.glsl): a 16-byte count, then 16 bytes a record of up
// to 64 blocks of 16 x 16 texels. Every large triangle takes a record at least, so the list is sized by
// triangles as much as by texels: a record for every 32 texels of the map (8 MiB at 4096²). At 65,536
// records (one per 256 texels), 64 soldiers seen from high above, whose map fitted to them makes most of
// their 71,424 triangles large, filled it, and the overflow's walk per thread took 6 ms on the H100.
// A full list only sends the rest back to that slower walk.
constexpr std::uint64_t kRecordHeaderBytes = 16;  // the count, padded
constexpr std::uint64_t kRecordBytes = 16;
constexpr std::uint64_t kTexelsPerRecord = 32;
// Workgroups of the records' dispatch: enough to fill a large GPU, few enough to cost next to nothing
// when no record is listed (the crowd's usual frame). Sizing it by what was listed (an indirect
// dispatch) measured 0.005-0.014 ms slower on the H100 in every frame tried, large crowds included.
constexpr std::uint32_t kRecordGroups = 1024;

std::uint64_t texelsOf(std::uint32_t size) { return std::uint64_t{size} * size; }
std::uint64_t recordBytesOf(std::uint32_t size) {
    return kRecordHeaderBytes + std::max<std::uint64_t>(texelsOf(size) / kTexelsPerRecord, 64) * kRecordBytes;
}
// Two 16-bit texels a word, the last word half used when the count is odd.
std::uint64_t packedWordsOf(std::uint32_t size) { return (texelsOf(size) + 1) / 2; }

}  // namespace

// texel = ((clip * k + o) * side + 2 corner + side) * size / 2 (render/shadow_cascades.h: ShadowCascades::
// fromFirst and the square).
ShadowRasterLight shadowRasterLight(const ShadowCascades& cascades, std::uint32_t mapSize) {
    ShadowRasterLight l{};
    const glm::mat4& m = cascades.clip[0];
    for (int row = 0; row < 3; ++row) l.light[row] = glm::vec4(m[0][row], m[1][row], m[2][row], m[3][row]);
    const float half = 0.5f * static_cast<float>(mapSize);
    for (std::uint32_t c = 0; c < cascades.count; ++c) {
        const glm::vec4 f = cascades.fromFirst[c], s = cascades.square[c];
        l.toTexels[c] = glm::vec4(glm::vec2(f) * s.z * half, (glm::vec2(f.z, f.w) * s.z + 2.0f * glm::vec2(s) + s.z) * half);
    }
    return l;
}

ShadowRaster::ShadowRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const DrawLists& lists,
                           const ShadowMap& map)
    : context_(context), pool_(pool), lists_(lists), size_(map.size()) {
    static_assert(kShadowFormat == VK_FORMAT_D16_UNORM, "shadow_pack.comp.glsl writes 16-bit unorm texels");
    depth_ = gpu::createBuffer(context, texelsOf(size_) * 4,
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               gpu::MemoryUse::DeviceLocal, "shadow map depth (compute raster)");
    try {
        records_ = gpu::createBuffer(context, recordBytesOf(size_),
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                     gpu::MemoryUse::DeviceLocal, "shadow map large triangles' records (compute raster)");
        packed_ = gpu::createBuffer(context, packedWordsOf(size_) * 4,
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    gpu::MemoryUse::DeviceLocal, "shadow map texels (compute raster, packed)");
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding bindings[] = {{storage, depth_.buffer}, {storage, packed_.buffer}};
        packSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(std::uint32_t)};
        const VkDescriptorSetLayout sets[] = {packSet_->layout()};
        packLayout_ = gpu::createPipelineLayout(context, sets, {&push, 1});
        packPipeline_ = gpu::createComputePipeline(context, shadow_pack_comp_spv, packLayout_, {});
    } catch (...) {
        release();
        throw;
    }
}

std::uint64_t ShadowRaster::bytesFor(std::uint32_t size) {
    return texelsOf(size) * 4 + packedWordsOf(size) * 4 + recordBytesOf(size);
}

bool ShadowRaster::fits(const VkPhysicalDeviceLimits& limits, std::uint32_t size) {
    const std::uint64_t largest = std::max({texelsOf(size) * 4, packedWordsOf(size) * 4, recordBytesOf(size)});
    return largest <= limits.maxStorageBufferRange;
}

ShadowRaster::~ShadowRaster() { release(); }

void ShadowRaster::release() {
    if (rasterPipeline_) vkDestroyPipeline(context_.device, rasterPipeline_, nullptr);
    if (recordPipeline_) vkDestroyPipeline(context_.device, recordPipeline_, nullptr);
    if (rasterLayout_) vkDestroyPipelineLayout(context_.device, rasterLayout_, nullptr);
    rasterPipeline_ = VK_NULL_HANDLE;
    recordPipeline_ = VK_NULL_HANDLE;
    rasterLayout_ = VK_NULL_HANDLE;
    rasterSet_.reset();
    if (packPipeline_) vkDestroyPipeline(context_.device, packPipeline_, nullptr);
    if (packLayout_) vkDestroyPipelineLayout(context_.device, packLayout_, nullptr);
    packPipeline_ = VK_NULL_HANDLE;
    packLayout_ = VK_NULL_HANDLE;
    packSet_.reset();
    gpu::destroyBuffer(context_, packed_);
    gpu::destroyBuffer(context_, records_);
    gpu::destroyBuffer(context_, depth_);
}

bool ShadowRaster::canRead(const SkinnedVertices& vertices) const {
    return vertices.buffer && vertices.normalsOffset > 0 &&
           vertices.normalsOffset <= context_.properties.limits.maxStorageBufferRange;
}

void ShadowRaster::bindVertices(const SkinnedVertices& vertices) {
    if (vertices.buffer->buffer == boundVertices_) return;
    constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    const gpu::BufferBinding bindings[] = {{storage, lists_.draws().buffer},
                                           {storage, lists_.totals().buffer},
                                           {storage, pool_.indices().buffer},
                                           {storage, vertices.buffer->buffer, 0, vertices.normalsOffset},
                                           {storage, depth_.buffer},
                                           {storage, lists_.shadowStates().buffer},
                                           {storage, records_.buffer}};
    rasterSet_ = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
    if (!rasterPipeline_) {
        // Every later set has the same definition, so the layout made with the first one stays valid.
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(RasterPush)};
        const VkDescriptorSetLayout sets[] = {rasterSet_->layout()};
        rasterLayout_ = gpu::createPipelineLayout(context_, sets, {&push, 1});
        const std::uint32_t casters[] = {0}, records[] = {1};  // kRecordPass
        rasterPipeline_ = gpu::createComputePipeline(context_, shadow_raster_comp_spv, rasterLayout_, casters);
        recordPipeline_ = gpu::createComputePipeline(context_, shadow_raster_comp_spv, rasterLayout_, records);
    }
    boundVertices_ = vertices.buffer->buffer;
}

void ShadowRaster::rasterize(VkCommandBuffer cmd, const SkinnedVertices& vertices, const ShadowCascades& cascades) {
    bindVertices(vertices);
    // The previous frame's pack read the depths, and its records' dispatch the list: done before both
    // are cleared.
    constexpr gpu::Access kClear{VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    gpu::bufferBarrier(cmd, depth_.buffer, kComputeRead, kClear);
    gpu::bufferBarrier(cmd, records_.buffer, kComputeReadWrite, kClear);
    vkCmdFillBuffer(cmd, depth_.buffer, 0, VK_WHOLE_SIZE, kFarDepthBits);
    vkCmdFillBuffer(cmd, records_.buffer, 0, kRecordHeaderBytes, 0);
    gpu::bufferBarrier(cmd, depth_.buffer, kClear, kComputeReadWrite);
    gpu::bufferBarrier(cmd, records_.buffer, kClear, kComputeReadWrite);
    // The skinned vertices (a compute pass's or a copy's) and the lists (culling's) were written
    // for the graphics passes; this pass reads them as storage.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
    const std::uint32_t groups = lists_.drawCapacity();
    const std::uint32_t perRow = std::min(groups, kMostGroupsPerRow);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterPipeline_);
    const VkDescriptorSet set = rasterSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterLayout_, 0, 1, &set, 0, nullptr);
    // One dispatch, the cascade its z (shadow_raster.comp.glsl says why).
    const RasterPush push{shadowRasterLight(cascades, size_), glm::uvec4(size_, perRow, lists_.drawCapacity(), cascades.count)};
    vkCmdPushConstants(cmd, rasterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, perRow, (groups + perRow - 1) / perRow, cascades.count);
    // The large triangles' records, listed by the dispatch above, each drawn by a workgroup: the list and
    // the depths (both dispatches' atomic mins) made visible to the second.
    gpu::memoryBarrier(cmd, kComputeReadWrite, kComputeReadWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, recordPipeline_);
    vkCmdDispatch(cmd, kRecordGroups, 1, 1);
}

void ShadowRaster::pack(VkCommandBuffer cmd) {
    // The depths are final; the previous frame's copy into the map read the packed texels.
    gpu::bufferBarrier(cmd, depth_.buffer, kComputeReadWrite, kComputeRead);
    gpu::bufferBarrier(cmd, packed_.buffer, kCopyRead, kComputeWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, packPipeline_);
    const VkDescriptorSet set = packSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, packLayout_, 0, 1, &set, 0, nullptr);
    const auto texels = static_cast<std::uint32_t>(texelsOf(size_));
    vkCmdPushConstants(cmd, packLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof texels, &texels);
    const std::uint64_t groups = (packedWordsOf(size_) + kPackGroupSize - 1) / kPackGroupSize;
    vkCmdDispatch(cmd, static_cast<std::uint32_t>(std::min<std::uint64_t>(groups, kMostGroupsPerRow)), 1, 1);
    gpu::bufferBarrier(cmd, packed_.buffer, kComputeWrite, kCopyRead);
}

}  // namespace render
