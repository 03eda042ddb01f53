#include "render/crowd_buffers.h"

#include <cstring>

#include <algorithm>
#include <bit>
#include <numeric>
#include <string>

#include "gpu/barriers.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

std::uint32_t boneStrideFor(const gpu::VulkanContext& context, std::uint32_t jointCount) {
    return boneStrideFor(context.properties.limits, jointCount);
}

std::uint32_t boneStrideFor(const VkPhysicalDeviceLimits& limits, std::uint32_t jointCount) {
    const std::uint64_t align = std::lcm(std::lcm<std::uint64_t>(sizeof(gpu::BoneRows), limits.minUniformBufferOffsetAlignment),
                                         limits.minStorageBufferOffsetAlignment);
    const std::uint64_t bytes = (jointCount * sizeof(gpu::BoneRows) + align - 1) / align * align;
    return static_cast<std::uint32_t>(bytes / sizeof(gpu::BoneRows));
}

namespace {

BoneLayout planBones(const crowd::Crowd& crowd, const std::vector<std::uint32_t>& strides) {
    BoneLayout layout;
    layout.largestBlock = *std::max_element(strides.begin(), strides.end());
    layout.offsets.reserve(crowd.size());
    std::uint64_t rows = 0;
    for (const crowd::Character& c : crowd.characters()) {
        layout.offsets.push_back(static_cast<std::uint32_t>(std::min<std::uint64_t>(rows, UINT32_MAX)));
        rows += strides[c.model];
    }
    layout.totalRows = rows + layout.largestBlock;
    return layout;
}

}  // namespace

const char* boneBlocksName(BoneBlocks blocks) {
    return blocks == BoneBlocks::PerMeshSlot ? "per mesh slot" : "per character";
}

BoneLayout planBones(const gpu::VulkanContext& context, const crowd::Crowd& crowd, BoneBlocks blocks,
                     std::uint32_t slots) {
    return planBones(context.properties.limits, crowd, blocks, slots);
}

BoneLayout planBones(const VkPhysicalDeviceLimits& limits, const crowd::Crowd& crowd, BoneBlocks blocks,
                     std::uint32_t slots) {
    std::vector<std::uint32_t> aligned, tight;
    for (const model::SkinnedModel* m : crowd.models()) {
        tight.push_back(static_cast<std::uint32_t>(m->skeleton.jointCount()));
        aligned.push_back(boneStrideFor(limits, tight.back()));
    }
    BoneLayout layout = planBones(crowd, aligned);
    // Alignment costs up to a few rows a character: millions of characters may fit only without it.
    if (layout.bytes() > limits.maxStorageBufferRange) {
        layout = planBones(crowd, tight);
        layout.aligned = false;
    }
    return withBlocks(std::move(layout), blocks, slots);
}

BoneLayout withBlocks(BoneLayout perCharacter, BoneBlocks blocks, std::uint32_t slots) {
    if (blocks == BoneBlocks::PerMeshSlot) {
        // The per-character layout's block size, so the vs baseline's pipeline and uniform range (made
        // for the largest block) stay valid across a switch between the two.
        perCharacter.blocks = BoneBlocks::PerMeshSlot;
        perCharacter.totalRows = std::uint64_t{std::max(slots, 1u)} * perCharacter.largestBlock;
    }
    return perCharacter;
}

std::vector<gpu::CharacterRecord> characterRecords(const crowd::Crowd& crowd, std::span<const std::uint32_t> boneOffsets) {
    std::vector<gpu::CharacterRecord> records(crowd.size());
    std::vector<std::uint32_t> ranks(crowd.models().size(), 0);
    for (std::uint32_t i = 0; i < crowd.size(); ++i) {
        const crowd::Character& c = crowd.characters()[i];
        const crowd::Identity identity = crowd.identity(i);  // a free slot's scale 0: culling skips it
        records[i].placement = glm::vec4(c.position, c.heading);
        records[i].tint = identity.tintScale;
        records[i].ids = glm::uvec4(c.model, boneOffsets[i], ranks[c.model]++, 0u);
        records[i].pose.z = static_cast<float>(identity.props);  // below 2^MAX_PROPS: exact
        records[i].pose.w = std::bit_cast<float>(identity.generation);
        if (crowd.alive(i)) crowd.poseRecord(i, crowd.epoch(), records[i]);  // near where it was advanced to
    }
    return records;
}

CrowdBuffers::CrowdBuffers(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t framesInFlight,
                           BoneBlocks blocks, std::uint32_t slots)
    : context_(context),
      slots_(slots),
      perCharacter_(planBones(context, crowd, BoneBlocks::PerCharacter, slots)),
      layout_(withBlocks(perCharacter_, blocks, slots)) {
    records_ = characterRecords(crowd, layout_.offsets);
    try {
        // Transfer source too: tests read back the records the motion pass wrote.
        characters_ = gpu::createBufferWithData(context, std::as_bytes(std::span(records_)),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                "character records");
        bones_ = allocateBones(layout_);
        staging_.resize(framesInFlight);
    } catch (...) {
        release();
        throw;
    }
}

gpu::Buffer CrowdBuffers::allocateBones(const BoneLayout& layout) const {
    const VkDeviceSize boneBytes = layout.bytes();
    // Offsets are 32-bit BoneRows indices in the shaders; the storage range bounds what one binding sees.
    if (boneBytes > context_.properties.limits.maxStorageBufferRange || layout.totalRows > UINT32_MAX)
        throw gpu::Error("a crowd of " + std::to_string(records_.size()) + " characters: bone matrices (" +
                             boneBlocksName(layout.blocks) + ") need " + gpu::formatBytes(boneBytes) +
                             ", over this device's storage-buffer limit of " +
                             gpu::formatBytes(context_.properties.limits.maxStorageBufferRange),
                         gpu::ErrorKind::OutOfDeviceMemory);
    return gpu::createBuffer(context_, boneBytes,
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             gpu::MemoryUse::DeviceLocal, "bone matrices");
}

void CrowdBuffers::setBoneBlocks(BoneBlocks blocks) {
    if (blocks == layout_.blocks) return;
    // The new buffer first: if it cannot be had, nothing changes.
    BoneLayout next = withBlocks(perCharacter_, blocks, slots_);
    gpu::Buffer bones = allocateBones(next);
    gpu::destroyBuffer(context_, bones_);
    bones_ = bones;
    // The bone staging is sized for the bones: made again on first use.
    for (Staging& s : staging_) gpu::destroyBuffer(context_, s.bones);
    // Per slot, the emit pass rewrites ids.y each frame; per character it must be the character's own.
    recordsStale_ = layout_.blocks == BoneBlocks::PerMeshSlot;
    layout_ = std::move(next);
}

CrowdBuffers::~CrowdBuffers() { release(); }

void CrowdBuffers::release() {
    for (Staging& s : staging_) {
        gpu::destroyBuffer(context_, s.bones);
        gpu::destroyBuffer(context_, s.records);
    }
    staging_.clear();
    gpu::destroyBuffer(context_, bones_);
    gpu::destroyBuffer(context_, characters_);
}

CrowdBuffers::Staging& CrowdBuffers::staging(std::uint32_t frameSlot) {
    // Made the first time the CPU path (or a records upload) runs: the GPU path never needs host copies.
    Staging& s = staging_[frameSlot];
    if (!s.records.buffer)
        s.records = gpu::createBuffer(context_, characters_.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                      gpu::MemoryUse::HostUpload, "character records (upload)");
    return s;
}

std::span<gpu::BoneRows> CrowdBuffers::boneStaging(std::uint32_t frameSlot) {
    Staging& s = staging(frameSlot);
    if (!s.bones.buffer)
        s.bones = gpu::createBuffer(context_, bones_.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::HostUpload,
                                    "bone matrices (upload)");
    return {static_cast<gpu::BoneRows*>(s.bones.mapped), static_cast<std::size_t>(layout_.totalRows)};
}

void CrowdBuffers::recordCpuAnimationUpload(VkCommandBuffer cmd, std::uint32_t frameSlot) {
    Staging& s = staging(frameSlot);
    boneStaging(frameSlot);
    std::memcpy(s.records.mapped, records_.data(), records_.size() * sizeof(gpu::CharacterRecord));
    // The previous frames' passes must be done reading before the copies overwrite bones and records.
    gpu::memoryBarrier(cmd, {kCharacterReaders, 0}, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkBufferCopy bones{0, 0, bones_.size};
    vkCmdCopyBuffer(cmd, s.bones.buffer, bones_.buffer, 1, &bones);
    const VkBufferCopy records{0, 0, characters_.size};
    vkCmdCopyBuffer(cmd, s.records.buffer, characters_.buffer, 1, &records);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});
    recordsStale_ = false;
}

void CrowdBuffers::recordRecordsUploadIfStale(VkCommandBuffer cmd, std::uint32_t frameSlot) {
    if (!recordsStale_) return;
    // The CPU's records hold every character's own block in ids.y; their motion fields may be old, but
    // the motion pass that follows rewrites those.
    Staging& s = staging(frameSlot);
    std::memcpy(s.records.mapped, records_.data(), records_.size() * sizeof(gpu::CharacterRecord));
    gpu::memoryBarrier(cmd, {kCharacterReaders, 0}, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkBufferCopy records{0, 0, characters_.size};
    vkCmdCopyBuffer(cmd, s.records.buffer, characters_.buffer, 1, &records);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    recordsStale_ = false;
}

void CrowdBuffers::updateRecords(const crowd::Crowd& crowd, double time) {
    crowd::WorkerPool::shared().parallelFor(crowd.size(), 1024, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i)
            if (crowd.alive(i)) crowd.poseRecord(i, time, records_[i]);
    });
}

}  // namespace render
