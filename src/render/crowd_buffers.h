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

// Every stage that reads the character records or the bones.
constexpr VkPipelineStageFlags2 kCharacterReaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

// Bones of a model with `jointCount` joints occupy this many BoneRows per character; the stride keeps
// every character's block aligned for a dynamic uniform-buffer offset (the vertex-shader baseline)
// and a storage offset.
std::uint32_t boneStrideFor(const gpu::VulkanContext& context, std::uint32_t jointCount);
std::uint32_t boneStrideFor(const VkPhysicalDeviceLimits& limits, std::uint32_t jointCount);

// Where every character's bone block starts (in BoneRows), and the buffer's size: blocks in character
// order, then room for one more of the largest block, so the baseline's fixed uniform range (the
// largest block) never reads past the end from the last character's offset.
struct BoneLayout {
    std::vector<std::uint32_t> offsets;
    std::uint32_t largestBlock = 0;  // BoneRows
    std::uint64_t totalRows = 0;
    // Blocks at offsets a dynamic uniform binding may take (the vs method needs it); false when the
    // crowd's bones only fit the storage-buffer range packed tightly (joints x 48 bytes apiece).
    bool aligned = true;
    std::uint64_t bytes() const { return totalRows * sizeof(gpu::BoneRows); }
};
// Aligned blocks when they fit the device's storage-buffer range, else tightly packed ones.
BoneLayout planBones(const gpu::VulkanContext& context, const crowd::Crowd& crowd);
BoneLayout planBones(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd);

// The GPU records of the crowd's characters.
std::vector<gpu::CharacterRecord> characterRecords(const crowd::Crowd& crowd, std::span<const std::uint32_t> boneOffsets);

class CrowdBuffers {
public:
    // Throws gpu::Error when the bones exceed the device's storage-buffer range or memory.
    CrowdBuffers(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t framesInFlight);
    ~CrowdBuffers();
    CrowdBuffers(const CrowdBuffers&) = delete;
    CrowdBuffers& operator=(const CrowdBuffers&) = delete;

    // The CPU animation path: where it writes this frame's bone matrices (host-visible, mapped; made
    // on first use), and the copies of those bones and of records() to the device, with their barriers.
    std::span<gpu::BoneRows> boneStaging(std::uint32_t frameSlot);
    void recordCpuAnimationUpload(VkCommandBuffer cmd, std::uint32_t frameSlot);
    // The CPU's copy of the records, for the CPU path to write and the CPU cull reference to read.
    std::span<gpu::CharacterRecord> mutableRecords() { return records_; }
    // Recomputes the motion fields of records() at `time` on the CPU (what the GPU motion pass writes
    // on the device), for the CPU cull reference.
    void updateRecords(const crowd::Crowd& crowd, double time);

    const gpu::Buffer& characters() const { return characters_; }
    const gpu::Buffer& bones() const { return bones_; }
    const std::vector<gpu::CharacterRecord>& records() const { return records_; }
    std::span<const std::uint32_t> boneOffsets() const { return layout_.offsets; }
    std::uint32_t largestBoneBlock() const { return layout_.largestBlock; }
    bool bonesAligned() const { return layout_.aligned; }
    std::uint32_t characterCount() const { return static_cast<std::uint32_t>(records_.size()); }
    VkDeviceSize deviceBytes() const { return characters_.size + bones_.size; }

private:
    void release();

    const gpu::VulkanContext& context_;
    BoneLayout layout_;
    std::vector<gpu::CharacterRecord> records_;
    gpu::Buffer characters_;
    gpu::Buffer bones_;
    struct Staging {
        gpu::Buffer bones, records;
    };
    Staging& staging(std::uint32_t frameSlot);
    std::vector<Staging> staging_;
};

}  // namespace render
