#pragma once
// Pass 2's vertex buffer for the methods that skin before drawing: every character's skinned
// world-space positions (RGBA32F), then every character's normals (xyz + material index).
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "skin/skinning_method.h"

namespace skin {

class SkinnedVertexBuffer {
public:
    // `writerUsage`: how the skinning pass writes it (TRANSFER_DST for copies, STORAGE_BUFFER for shaders).
    SkinnedVertexBuffer(const gpu::VulkanContext& context, std::uint32_t characterCount, std::uint32_t characterStride,
                        VkBufferUsageFlags writerUsage);
    ~SkinnedVertexBuffer();
    SkinnedVertexBuffer(const SkinnedVertexBuffer&) = delete;
    SkinnedVertexBuffer& operator=(const SkinnedVertexBuffer&) = delete;

    SkinnedVertices vertices() const { return {&buffer_, streamBytes(), characterStride_}; }
    VkBuffer buffer() const { return buffer_.buffer; }
    VkDeviceSize streamBytes() const { return buffer_.size / 2; }
    VkDeviceSize bytes() const { return buffer_.size; }

    // Before the skinning pass writes: the previous frame's draw must be done reading.
    void barrierBeforeWrite(VkCommandBuffer cmd, gpu::Access writer) const;
    // After it wrote: make the writes visible to the draw's vertex fetch (and to test readbacks).
    void barrierAfterWrite(VkCommandBuffer cmd, gpu::Access writer) const;

private:
    const gpu::VulkanContext& context_;
    gpu::Buffer buffer_;
    std::uint32_t characterStride_;
};

// The storage bindings of a skinning shader that writes this buffer: bind-pose vertices, bones,
// positions, normals (the last two are the buffer's two halves).
std::array<gpu::BufferBinding, 4> skinningBindings(const render::CrowdBuffers& crowd, const SkinnedVertexBuffer& skinned);

}  // namespace skin
