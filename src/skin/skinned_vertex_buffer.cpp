#include "skin/skinned_vertex_buffer.h"

#include "gpu/vulkan_context.h"
#include "render/crowd_buffers.h"

namespace skin {

SkinnedVertexBuffer::SkinnedVertexBuffer(const gpu::VulkanContext& context, std::uint32_t characterCount,
                                         std::uint32_t characterStride, VkBufferUsageFlags writerUsage)
    : context_(context), characterStride_(characterStride) {
    const VkDeviceSize stream = static_cast<VkDeviceSize>(characterCount) * characterStride * sizeof(glm::vec4);
    buffer_ = gpu::createBuffer(context, 2 * stream,
                                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | writerUsage,
                                gpu::MemoryUse::DeviceLocal, "skinned vertex buffer");
}

SkinnedVertexBuffer::~SkinnedVertexBuffer() { gpu::destroyBuffer(context_, buffer_); }

void SkinnedVertexBuffer::barrierBeforeWrite(VkCommandBuffer cmd, gpu::Access writer) const {
    gpu::bufferBarrier(cmd, buffer_.buffer, {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, 0}, writer);
}

void SkinnedVertexBuffer::barrierAfterWrite(VkCommandBuffer cmd, gpu::Access writer) const {
    gpu::bufferBarrier(cmd, buffer_.buffer, writer,
                       {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT});
}

std::array<gpu::BufferBinding, 4> skinningBindings(const render::CrowdBuffers& crowd, const SkinnedVertexBuffer& skinned) {
    const VkDeviceSize half = skinned.streamBytes();
    return {{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd.bindVertices().buffer},
             {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd.bones().buffer},
             {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, skinned.buffer(), 0, half},
             {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, skinned.buffer(), half, half}}};
}

}  // namespace skin
