#pragma once
// The skinned vertices a method produces for the draw pass: every skinned vertex's world-space
// position (RGBA32F), then every normal (xyz + pooled material index), in the slots culling assigned
// (render/draw_lists.h).
#include <array>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/character_draw.h"

namespace skin {

class SkinnedVertexBuffer {
public:
    // `writerUsage`: how the skinning pass writes it (TRANSFER_DST for copies, STORAGE_BUFFER for shaders).
    // Throws gpu::Error when `capacity` vertices cannot be addressed by a draw's 32-bit vertexOffset.
    SkinnedVertexBuffer(const gpu::VulkanContext& context, std::uint64_t capacity, VkBufferUsageFlags writerUsage);
    ~SkinnedVertexBuffer();
    SkinnedVertexBuffer(const SkinnedVertexBuffer&) = delete;
    SkinnedVertexBuffer& operator=(const SkinnedVertexBuffer&) = delete;

    static std::uint64_t bytesFor(std::uint64_t capacity) { return capacity * 2 * sizeof(glm::vec4); }

    render::SkinnedVertices vertices() const { return {&buffer_, streamBytes()}; }
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
};

}  // namespace skin
