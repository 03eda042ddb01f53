#include "render/crowd_buffers.h"

#include <numeric>

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

CrowdBuffers::CrowdBuffers(const gpu::VulkanContext& context, const model::SkinnedModel& model,
                           std::uint32_t characterCount, std::uint32_t framesInFlight)
    : context_(context),
      vertexCount_(static_cast<std::uint32_t>(model.vertices.size())),
      indexCount_(static_cast<std::uint32_t>(model.indices.size())),
      jointCount_(static_cast<std::uint32_t>(model.skeleton.jointCount())),
      characterCount_(characterCount),
      boneStride_(boneStrideFor(context, jointCount_)) {
    const VkDeviceSize boneBytes = static_cast<VkDeviceSize>(characterCount) * boneStride_ * sizeof(gpu::BoneRows);
    if (boneBytes > context.properties.limits.maxStorageBufferRange)
        throw gpu::Error("--count " + std::to_string(characterCount) + ": bone matrices need " +
                         gpu::formatBytes(boneBytes) + ", over this device's storage-buffer limit of " +
                         gpu::formatBytes(context.properties.limits.maxStorageBufferRange));
    try {
        bindVertices_ = gpu::createBufferWithData(context, std::as_bytes(std::span(model.vertices)),
                                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                  "bind-pose vertices");
        indices_ = gpu::createBufferWithData(context, std::as_bytes(std::span(model.indices)),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "indices");
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
    gpu::destroyBuffer(context_, indices_);
    gpu::destroyBuffer(context_, bindVertices_);
}

std::span<gpu::BoneRows> CrowdBuffers::boneStaging(std::uint32_t frameSlot) {
    return {static_cast<gpu::BoneRows*>(boneStaging_[frameSlot].mapped),
            static_cast<std::size_t>(characterCount_) * boneStride_};
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
