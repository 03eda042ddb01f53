#pragma once
// The crowd's per-character GPU data: one gpu::CharacterRecord per character (placement, tint,
// model, where its bones are) and the bone matrices of every character, uploaded each frame.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu_types.h"

namespace gpu { class VulkanContext; }

namespace render {

// Bones of a model with `jointCount` joints occupy this many BoneRows per character; the stride keeps
// every character's block aligned for a dynamic uniform-buffer offset (the vertex-shader baseline)
// and a storage offset.
std::uint32_t boneStrideFor(const gpu::VulkanContext& context, std::uint32_t jointCount);

// Where every character's bone block starts (in BoneRows), and the buffer's size: blocks in character
// order, then room for one more of the largest block, so the baseline's fixed uniform range (the
// largest block) never reads past the end from the last character's offset.
struct BoneLayout {
    std::vector<std::uint32_t> offsets;
    std::uint32_t largestBlock = 0;  // BoneRows
    std::uint64_t totalRows = 0;
    std::uint64_t bytes() const { return totalRows * sizeof(gpu::BoneRows); }
};
BoneLayout planBones(const gpu::VulkanContext& context, const crowd::Crowd& crowd);

// The GPU records of the crowd's characters.
std::vector<gpu::CharacterRecord> characterRecords(const crowd::Crowd& crowd, std::span<const std::uint32_t> boneOffsets);

class CrowdBuffers {
public:
    // Throws gpu::Error when the bones exceed the device's storage-buffer range or memory.
    CrowdBuffers(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t framesInFlight);
    ~CrowdBuffers();
    CrowdBuffers(const CrowdBuffers&) = delete;
    CrowdBuffers& operator=(const CrowdBuffers&) = delete;

    // Where the CPU writes this frame's bone matrices (host-visible, mapped).
    std::span<gpu::BoneRows> boneStaging(std::uint32_t frameSlot);
    // Copies this frame's bones to the device-local bone buffer, with the barriers around it.
    void recordBoneUpload(VkCommandBuffer cmd, std::uint32_t frameSlot) const;

    const gpu::Buffer& characters() const { return characters_; }
    const gpu::Buffer& bones() const { return bones_; }
    const std::vector<gpu::CharacterRecord>& records() const { return records_; }
    std::span<const std::uint32_t> boneOffsets() const { return layout_.offsets; }
    std::uint32_t largestBoneBlock() const { return layout_.largestBlock; }
    std::uint32_t characterCount() const { return static_cast<std::uint32_t>(records_.size()); }
    VkDeviceSize deviceBytes() const { return characters_.size + bones_.size; }

private:
    void release();

    const gpu::VulkanContext& context_;
    BoneLayout layout_;
    std::vector<gpu::CharacterRecord> records_;
    gpu::Buffer characters_;
    gpu::Buffer bones_;
    std::vector<gpu::Buffer> boneStaging_;
};

}  // namespace render
