#include "skin/skinned_vertex_buffer.h"

#include <algorithm>
#include <string>

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace skin {

SkinnedVertexBuffer::SkinnedVertexBuffer(const gpu::VulkanContext& context, std::uint64_t capacity,
                                         VkBufferUsageFlags writerUsage)
    : context_(context) {
    if (capacity > static_cast<std::uint64_t>(INT32_MAX))
        throw gpu::Error(std::to_string(capacity) + " skinned vertices are more than a draw's vertexOffset can reach (" +
                         std::to_string(INT32_MAX) + ")");
    buffer_ = gpu::createBuffer(context, std::max<VkDeviceSize>(bytesFor(capacity), 2 * sizeof(glm::vec4)),
                                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | writerUsage,
                                gpu::MemoryUse::DeviceLocal, "skinned vertex buffer");
    // Shaders that store into it bind each stream whole (app/storage_ranges.h refuses such crowds first).
    if ((writerUsage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) && streamBytes() > context.properties.limits.maxStorageBufferRange) {
        gpu::destroyBuffer(context, buffer_);
        throw gpu::Error("skinned vertices: " + gpu::formatBytes(bytesFor(capacity) / 2) +
                         " per stream, over this device's storage-buffer range of " +
                         gpu::formatBytes(context.properties.limits.maxStorageBufferRange));
    }
}

SkinnedVertexBuffer::~SkinnedVertexBuffer() { gpu::destroyBuffer(context_, buffer_); }

void SkinnedVertexBuffer::barrierBeforeWrite(VkCommandBuffer cmd, gpu::Access writer) const {
    gpu::bufferBarrier(cmd, buffer_.buffer, {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT, 0},
                       writer);
}

void SkinnedVertexBuffer::barrierAfterWrite(VkCommandBuffer cmd, gpu::Access writer) const {
    gpu::bufferBarrier(cmd, buffer_.buffer, writer,
                       {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT});
}

}  // namespace skin
