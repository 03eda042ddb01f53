#include "render/far_crowd_layer.h"

#include <algorithm>
#include <cstddef>
#include <span>

#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu_types.h"
#include "far_crowd_resolve.frag.spv.h"

namespace render {

namespace {
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
// Cleared and written each frame, read back by the tests.
constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

struct ResolvePush {
    glm::vec4 cameraPosition;
    glm::vec4 viewport;  // offset, extent
};
// The tiles' vertex shader (visibility_tiles.vert.glsl) reads the viewport there.
static_assert(offsetof(ResolvePush, viewport) == 16);

// The layer's two buffers' bytes at `extent`: a 64-bit depth word a pixel, and FAR_CROWD_CHANNELS
// 32-bit sums a pixel.
std::uint64_t pixelsOf(VkExtent2D extent) { return std::uint64_t{extent.width} * extent.height; }
std::uint64_t depthBytes(VkExtent2D extent) { return pixelsOf(extent) * 8; }
std::uint64_t sumsBytes(VkExtent2D extent) { return pixelsOf(extent) * FAR_CROWD_CHANNELS * 4; }
}  // namespace

FarCrowdLayer::FarCrowdLayer(const gpu::VulkanContext& context, VkDescriptorSetLayout sceneSetLayout,
                             const TargetFormat& target, std::uint32_t framesInFlight, std::uint32_t resolveTilePixels)
    : context_(context), slots_(framesInFlight) {
    try {
        for (std::uint32_t slot = 0; slot < framesInFlight; ++slot) fit(slot, {1, 1});
        const gpu::BufferBinding shape[2] = {{kStorage, slots_[0].depth.buffer}, {kStorage, slots_[0].sums.buffer}};
        prototype_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_FRAGMENT_BIT, shape);
        const VkDescriptorSetLayout sets[2] = {sceneSetLayout, prototype_->layout()};
        const VkPushConstantRange push{kResolvePushStages, 0, sizeof(ResolvePush)};
        layout_ = gpu::createPipelineLayout(context, sets, {&push, 1});
        resolve_ = std::make_unique<VisibilityResolve>(context, far_crowd_resolve_frag_spv, layout_, target,
                                                       framesInFlight, resolveTilePixels, ResolveWrite::LayerOver);
    } catch (...) {
        release();
        throw;
    }
}

FarCrowdLayer::~FarCrowdLayer() { release(); }

void FarCrowdLayer::release() {
    resolve_.reset();
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
    prototype_.reset();
    for (Slot& slot : slots_) {
        slot.resolveSet.reset();
        gpu::destroyBuffer(context_, slot.depth);
        gpu::destroyBuffer(context_, slot.sums);
    }
}

bool FarCrowdLayer::fits(const VkPhysicalDeviceLimits& limits, VkExtent2D extent) {
    return std::max(depthBytes(extent), sumsBytes(extent)) <= limits.maxStorageBufferRange;
}

void FarCrowdLayer::fit(std::uint32_t index, VkExtent2D extent) {
    Slot& slot = slots_[index];
    if (slot.depth.buffer && extent.width == slot.extent.width && extent.height == slot.extent.height) return;
    slot.resolveSet.reset();
    gpu::destroyBuffer(context_, slot.depth);
    gpu::destroyBuffer(context_, slot.sums);
    slot.extent = extent;
    slot.depth = gpu::createBuffer(context_, depthBytes(extent), kUsage, gpu::MemoryUse::DeviceLocal, "far crowd depth");
    slot.sums = gpu::createBuffer(context_, sumsBytes(extent), kUsage, gpu::MemoryUse::DeviceLocal, "far crowd sums");
    const gpu::BufferBinding bindings[2] = {{kStorage, slot.depth.buffer}, {kStorage, slot.sums.buffer}};
    slot.resolveSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_FRAGMENT_BIT, bindings);
}

void FarCrowdLayer::recordClear(VkCommandBuffer cmd, std::uint32_t index) const {
    const Slot& slot = slots_[index];
    vkCmdFillBuffer(cmd, slot.depth.buffer, 0, VK_WHOLE_SIZE, VISIBILITY_EMPTY_HIGH);
    vkCmdFillBuffer(cmd, slot.sums.buffer, 0, VK_WHOLE_SIZE, 0u);
}

void FarCrowdLayer::recordTiles(VkCommandBuffer cmd, std::uint32_t index) {
    resolve_->recordTiles(cmd, index, slots_[index].depth, slots_[index].extent);
}

void FarCrowdLayer::recordResolve(VkCommandBuffer cmd, std::uint32_t index, VkDescriptorSet sceneSet,
                                  const glm::vec3& eye, const VkRect2D& viewport) const {
    const Slot& slot = slots_[index];
    resolve_->bind(cmd);
    const VkDescriptorSet sets[2] = {sceneSet, slot.resolveSet->set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 2, sets, 0, nullptr);
    const ResolvePush push{glm::vec4(eye, 1.0f),
                           glm::vec4(static_cast<float>(viewport.offset.x), static_cast<float>(viewport.offset.y),
                                     static_cast<float>(slot.extent.width), static_cast<float>(slot.extent.height))};
    vkCmdPushConstants(cmd, layout_, kResolvePushStages, 0, sizeof push, &push);
    resolve_->draw(cmd, index);
}

std::uint64_t FarCrowdLayer::bytes() const {
    std::uint64_t total = resolve_ ? resolve_->bytes() : 0;
    for (const Slot& slot : slots_) total += slot.depth.size + slot.sums.size;
    return total;
}

}  // namespace render
