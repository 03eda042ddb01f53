#pragma once
// The crowd's GPU inputs that every skinning method reads: the model's bind-pose vertices and
// indices, and the bone matrices of every character, uploaded each frame.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu_types.h"
#include "model/skinned_model.h"

namespace gpu { class VulkanContext; }

namespace render {

// Bones of one character occupy `boneStride` BoneRows; the stride keeps every character's block
// aligned for a dynamic uniform-buffer offset (the vertex-shader baseline) and a storage offset.
std::uint32_t boneStrideFor(const gpu::VulkanContext& context, std::uint32_t jointCount);

class CrowdBuffers {
public:
    CrowdBuffers(const gpu::VulkanContext& context, const model::SkinnedModel& model, std::uint32_t characterCount,
                 std::uint32_t framesInFlight);
    ~CrowdBuffers();
    CrowdBuffers(const CrowdBuffers&) = delete;
    CrowdBuffers& operator=(const CrowdBuffers&) = delete;

    // Where the CPU writes this frame's bone matrices (host-visible, mapped).
    std::span<gpu::BoneRows> boneStaging(std::uint32_t frameSlot);
    // Copies this frame's bones to the device-local bone buffer, with the barriers around it.
    void recordBoneUpload(VkCommandBuffer cmd, std::uint32_t frameSlot) const;

    const gpu::Buffer& bindVertices() const { return bindVertices_; }
    const gpu::Buffer& indices() const { return indices_; }
    const gpu::Buffer& bones() const { return bones_; }
    std::uint32_t vertexCount() const { return vertexCount_; }
    std::uint32_t indexCount() const { return indexCount_; }
    std::uint32_t jointCount() const { return jointCount_; }
    std::uint32_t characterCount() const { return characterCount_; }
    std::uint32_t boneStride() const { return boneStride_; }
    VkDeviceSize deviceBytes() const { return bindVertices_.size + indices_.size + bones_.size; }

private:
    void release();

    const gpu::VulkanContext& context_;
    gpu::Buffer bindVertices_;
    gpu::Buffer indices_;
    gpu::Buffer bones_;
    std::vector<gpu::Buffer> boneStaging_;
    std::uint32_t vertexCount_, indexCount_, jointCount_, characterCount_, boneStride_;
};

}  // namespace render
