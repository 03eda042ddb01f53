#include "render/crowd_buffers.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "gpu/barriers.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

std::uint32_t boneStrideFor(const gpu::VulkanContext& context, std::uint32_t jointCount) {
    const auto& limits = context.properties.limits;
    const std::uint64_t align = std::lcm(std::lcm<std::uint64_t>(sizeof(gpu::BoneRows), limits.minUniformBufferOffsetAlignment),
                                         limits.minStorageBufferOffsetAlignment);
    const std::uint64_t bytes = (jointCount * sizeof(gpu::BoneRows) + align - 1) / align * align;
    return static_cast<std::uint32_t>(bytes / sizeof(gpu::BoneRows));
}

BoneLayout planBones(const gpu::VulkanContext& context, const crowd::Crowd& crowd) {
    std::vector<std::uint32_t> strides;
    for (const model::SkinnedModel* m : crowd.models())
        strides.push_back(boneStrideFor(context, static_cast<std::uint32_t>(m->skeleton.jointCount())));
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

std::vector<gpu::CharacterRecord> characterRecords(const crowd::Crowd& crowd, std::span<const std::uint32_t> boneOffsets) {
    std::vector<gpu::CharacterRecord> records(crowd.size());
    std::vector<std::uint32_t> ranks(crowd.models().size(), 0);
    for (std::uint32_t i = 0; i < crowd.size(); ++i) {
        const crowd::Character& c = crowd.characters()[i];
        records[i].placement = glm::vec4(c.position, c.heading);
        records[i].tint = glm::vec4(c.tint, c.scale);
        records[i].ids = glm::uvec4(c.model, boneOffsets[i], ranks[c.model]++, 0u);
        crowd.poseRecord(i, 0.0f, records[i]);
    }
    return records;
}

CrowdBuffers::CrowdBuffers(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t framesInFlight)
    : context_(context), layout_(planBones(context, crowd)) {
    const VkDeviceSize boneBytes = layout_.bytes();
    // Offsets are 32-bit BoneRows indices in the shaders; the storage range bounds what one binding sees.
    if (boneBytes > context.properties.limits.maxStorageBufferRange || layout_.totalRows > UINT32_MAX)
        throw gpu::Error("--count " + std::to_string(crowd.size()) + ": bone matrices need " +
                         gpu::formatBytes(boneBytes) + ", over this device's storage-buffer limit of " +
                         gpu::formatBytes(context.properties.limits.maxStorageBufferRange));
    records_ = characterRecords(crowd, layout_.offsets);
    try {
        characters_ = gpu::createBufferWithData(context, std::as_bytes(std::span(records_)),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "character records");
        bones_ = gpu::createBuffer(context, boneBytes,
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   gpu::MemoryUse::DeviceLocal, "bone matrices");
        for (std::uint32_t i = 0; i < framesInFlight; ++i)
            boneStaging_.push_back(gpu::createBuffer(context, boneBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                     gpu::MemoryUse::HostUpload, "bone matrices (upload)"));
    } catch (...) {
        release();
        throw;
    }
}

CrowdBuffers::~CrowdBuffers() { release(); }

void CrowdBuffers::release() {
    for (gpu::Buffer& b : boneStaging_) gpu::destroyBuffer(context_, b);
    boneStaging_.clear();
    gpu::destroyBuffer(context_, bones_);
    gpu::destroyBuffer(context_, characters_);
}

std::span<gpu::BoneRows> CrowdBuffers::boneStaging(std::uint32_t frameSlot) {
    return {static_cast<gpu::BoneRows*>(boneStaging_[frameSlot].mapped), static_cast<std::size_t>(layout_.totalRows)};
}

void CrowdBuffers::recordBoneUpload(VkCommandBuffer cmd, std::uint32_t frameSlot) const {
    constexpr VkPipelineStageFlags2 readers = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    // The previous frame's shaders must be done reading before the copy overwrites the bones.
    gpu::bufferBarrier(cmd, bones_.buffer, {readers, 0}, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkBufferCopy region{0, 0, bones_.size};
    vkCmdCopyBuffer(cmd, boneStaging_[frameSlot].buffer, bones_.buffer, 1, &region);
    gpu::bufferBarrier(cmd, bones_.buffer, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {readers, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});
}

}  // namespace render
