#pragma once
// The crowd's per-character GPU data: one gpu::CharacterRecord per character (placement, tint,
// model, where its bones are) and the bone matrices: one block per mesh slot (the frame's draws), or
// one per character where the frame needs every character's bones (BoneBlocks).
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

// Whom a bone block belongs to.
//   PerMeshSlot: block i to the frame's draw i (DrawLists::draws), so at most the draw capacity (the
//     mesh capacity) of blocks, whatever the crowd's size: the GPU palette pass writes the block of the
//     slot a character got this frame, and the emit pass tells every reader where it is (ids.y of the
//     character's record). A character at the impostor level, or culled, has no block.
//   PerCharacter: block per character, fixed, at boneOffsets(): for what binds or writes bones
//     without the frame's slots: the vs baseline (CPU-recorded offsets), the CPU animation path
//     (uploads every character's bones) and the static method (skins every character once).
enum class BoneBlocks { PerMeshSlot, PerCharacter };
const char* boneBlocksName(BoneBlocks blocks);

// Where every character's own bone block starts (in BoneRows), and the buffer's size. Per character:
// blocks in character order, then room for one more of the largest block, so the baseline's fixed
// uniform range (the largest block) never reads past the end from the last character's offset. Per
// mesh slot: `slots` blocks of the largest block's size (a slot may hold any model); `offsets` still
// gives the per-character layout, which a later switch to it (and the records' first ids.y) uses.
struct BoneLayout {
    std::vector<std::uint32_t> offsets;
    std::uint32_t largestBlock = 0;  // BoneRows
    std::uint64_t totalRows = 0;
    // Blocks at offsets a dynamic uniform binding may take (the vs method needs it); false when the
    // crowd's bones only fit the storage-buffer range packed tightly (joints x 48 bytes apiece).
    bool aligned = true;
    BoneBlocks blocks = BoneBlocks::PerCharacter;
    std::uint64_t bytes() const { return totalRows * sizeof(gpu::BoneRows); }
    // BoneRows between slot i's block and slot i + 1's (0 per character: blocks are at `offsets`).
    std::uint32_t slotRows() const { return blocks == BoneBlocks::PerMeshSlot ? largestBlock : 0u; }
};
// Per character: aligned blocks when they fit the device's storage-buffer range, else tightly packed
// ones. Per mesh slot: `slots` blocks of the per-character layout's largest block.
BoneLayout planBones(const gpu::VulkanContext& context, const crowd::Crowd& crowd,
                     BoneBlocks blocks = BoneBlocks::PerCharacter, std::uint32_t slots = 0);
BoneLayout planBones(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd,
                     BoneBlocks blocks = BoneBlocks::PerCharacter, std::uint32_t slots = 0);

// A per-character layout (planBones') as `blocks` lays it out for `slots` mesh slots.
BoneLayout withBlocks(BoneLayout perCharacter, BoneBlocks blocks, std::uint32_t slots);

// The GPU records of the crowd's slots (a free slot's scale 0).
std::vector<gpu::CharacterRecord> characterRecords(const crowd::Crowd& crowd, std::span<const std::uint32_t> boneOffsets);

class CrowdBuffers {
public:
    // `slots`: the most characters a frame lists at a mesh level (DrawLists::drawCapacity), the blocks
    // per mesh slot. Throws gpu::Error when the bones exceed the device's storage-buffer range or memory.
    CrowdBuffers(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t framesInFlight,
                 BoneBlocks blocks, std::uint32_t slots);
    ~CrowdBuffers();
    CrowdBuffers(const CrowdBuffers&) = delete;
    CrowdBuffers& operator=(const CrowdBuffers&) = delete;

    // Between frames, with the GPU idle: reallocates the bones for the other kind of block (a new
    // buffer: whoever binds bones() binds it again; when it cannot be had, it throws and nothing changes). Leaving per-slot blocks, the device's records hold
    // slot offsets in ids.y: the next frame uploads the records first (recordRecordsUploadIfStale).
    void setBoneBlocks(BoneBlocks blocks);
    BoneBlocks boneBlocks() const { return layout_.blocks; }
    // BoneRows from one slot's block to the next, for the emit pass (0: blocks per character).
    std::uint32_t slotBoneRows() const { return layout_.slotRows(); }
    // After a switch to per-character blocks, the device's records are uploaded again (their ids.y);
    // the CPU animation path's upload does it too. No-op otherwise.
    void recordRecordsUploadIfStale(VkCommandBuffer cmd, std::uint32_t frameSlot);

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
    // A buffer for `layout`; throws when it is over the storage-buffer range.
    gpu::Buffer allocateBones(const BoneLayout& layout) const;

    const gpu::VulkanContext& context_;
    std::uint32_t slots_;
    BoneLayout perCharacter_;  // the crowd's blocks per character (a switch to them takes this layout)
    BoneLayout layout_;
    bool recordsStale_ = false;  // the device's ids.y hold slot offsets, per-character blocks need their own
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
