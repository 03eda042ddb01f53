#include "render/visibility_tiles.h"

#include <cstddef>
#include <span>
#include <string>

#include "gpu/barriers.h"
#include "gpu/error.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu_types.h"
#include "visibility_tiles.comp.spv.h"

namespace render {

namespace {
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
// Written by the scan, read by the indirect draw and as a vertex attribute, read back by the tests.
constexpr VkBufferUsageFlags kListUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
constexpr std::uint32_t kMaxTilePixels = 256;

std::uint32_t tilesAcross(std::uint32_t pixels, std::uint32_t tile) { return (pixels + tile - 1) / tile; }
}  // namespace

bool isResolveTileSide(std::uint32_t pixels) {
    return pixels > 0 && pixels <= kMaxTilePixels && pixels % VISIBILITY_TILE_GROUP == 0;
}

VisibilityTiles::VisibilityTiles(const gpu::VulkanContext& context, std::uint32_t framesInFlight, std::uint32_t tilePixels)
    : context_(context), tilePixels_(tilePixels), slots_(framesInFlight) {
    if (!isResolveTileSide(tilePixels))
        throw gpu::Error("the resolve's tile side must be a multiple of " + std::to_string(VISIBILITY_TILE_GROUP) +
                         " pixels up to " + std::to_string(kMaxTilePixels) + ", not " + std::to_string(tilePixels));
    try {
        // The slots' sets have this shape (made with their buffers); a layout of it serves the pipeline's.
        VkDescriptorSetLayoutBinding shape[2]{};
        for (std::uint32_t b = 0; b < 2; ++b) shape[b] = {b, kStorage, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        const VkDescriptorSetLayout setLayout = gpu::createSetLayout(context, shape);
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(glm::uvec4)};
        try {
            layout_ = gpu::createPipelineLayout(context, {&setLayout, 1}, {&push, 1});
        } catch (...) {
            vkDestroyDescriptorSetLayout(context.device, setLayout, nullptr);
            throw;
        }
        vkDestroyDescriptorSetLayout(context.device, setLayout, nullptr);
        const std::uint32_t constants[] = {tilePixels};
        pipeline_ = gpu::createComputePipeline(context, visibility_tiles_comp_spv, layout_, constants);
    } catch (...) {
        release();
        throw;
    }
}

VisibilityTiles::~VisibilityTiles() { release(); }

void VisibilityTiles::release() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE, layout_ = VK_NULL_HANDLE;
    for (Slot& slot : slots_) {
        slot.set.reset();
        gpu::destroyBuffer(context_, slot.list);
    }
}

void VisibilityTiles::makeSlot(std::uint32_t index, const gpu::Buffer& visibility, VkExtent2D extent) {
    Slot& slot = slots_[index];
    slot.set.reset();
    if (extent.width != slot.extent.width || extent.height != slot.extent.height || !slot.list.buffer) {
        gpu::destroyBuffer(context_, slot.list);
        const std::uint64_t tiles = std::uint64_t{tilesAcross(extent.width, tilePixels_)} * tilesAcross(extent.height, tilePixels_);
        slot.list = gpu::createBuffer(context_, sizeof(gpu::VisibilityTileList) + tiles * 4, kListUsage,
                                      gpu::MemoryUse::DeviceLocal, "visibility tiles");
        slot.extent = extent;
    }
    const gpu::BufferBinding bindings[] = {{kStorage, visibility.buffer}, {kStorage, slot.list.buffer}};
    slot.set = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
    slot.visibility = visibility.buffer;
}

void VisibilityTiles::record(VkCommandBuffer cmd, std::uint32_t index, const gpu::Buffer& visibility, VkExtent2D extent) {
    Slot& slot = slots_[index];
    if (extent.width != slot.extent.width || extent.height != slot.extent.height || slot.visibility != visibility.buffer)
        makeSlot(index, visibility, extent);
    // The slot's previous frame drew from the list (indirect and as a vertex attribute) after the scan
    // wrote it: both come before the header's reset.
    gpu::memoryBarrier(cmd,
                       {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const gpu::VisibilityTileList header{6u, 0u, 0u, 0u, 1u, 0u, 0u, 0u};
    vkCmdUpdateBuffer(cmd, slot.list.buffer, 0, sizeof header, &header);
    // The header's reset and the rasterizer's writes to the visibility buffer, before the scan.
    gpu::memoryBarrier(cmd,
                       {VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const VkDescriptorSet set = slot.set->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
    const glm::uvec4 push(extent.width, extent.height, 0u, 0u);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, tilesAcross(extent.width, tilePixels_), tilesAcross(extent.height, tilePixels_), 1);
    // The resolve's indirect draw reads the count, its vertex input the tiles.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT});
}

void VisibilityTiles::recordDraw(VkCommandBuffer cmd, std::uint32_t index) const {
    const Slot& slot = slots_[index];
    const VkDeviceSize tilesOffset = sizeof(gpu::VisibilityTileList);
    vkCmdBindVertexBuffers(cmd, 0, 1, &slot.list.buffer, &tilesOffset);
    // The Count form with a count of 1 rather than vkCmdDrawIndirect: lavapipe (Mesa 22.3) keeps the
    // count buffer of the Count draw before it (the impostors', render/impostor_draw.cpp) and draws
    // nothing. Same cost elsewhere.
    vkCmdDrawIndirectCount(cmd, slot.list.buffer, 0, slot.list.buffer, offsetof(gpu::VisibilityTileList, drawCount), 1,
                           sizeof(VkDrawIndirectCommand));
}

std::uint64_t VisibilityTiles::bytes() const {
    std::uint64_t total = 0;
    for (const Slot& slot : slots_) total += slot.list.size;
    return total;
}

}  // namespace render
