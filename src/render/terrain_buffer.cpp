#include "render/terrain_buffer.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "gpu/barriers.h"
#include "gpu/error.h"

namespace render {

std::uint32_t TerrainBuffer::samplesFor(const crowd::Crowd& crowd, std::uint32_t asked) {
    return std::max({asked, static_cast<std::uint32_t>(crowd.terrain().heights().size()), 4u});
}

TerrainBuffer::TerrainBuffer(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t samples,
                             std::uint32_t framesInFlight)
    : context_(context), capacity_(samplesFor(crowd, samples)), staging_(framesInFlight) {
    // Zeros until the first upload: flat, as the grid says (extent z = 0) until then.
    const std::vector<float> zeros(capacity_, 0.0f);
    heights_ = gpu::createBufferWithData(context, std::as_bytes(std::span(zeros)),
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         "terrain heights");
    grid_ = crowd::Terrain().grid();
}

TerrainBuffer::~TerrainBuffer() {
    for (gpu::Buffer& b : staging_) gpu::destroyBuffer(context_, b);
    gpu::destroyBuffer(context_, heights_);
}

void TerrainBuffer::check(const crowd::Crowd& crowd) const {
    if (crowd.terrain().heights().size() > capacity_)
        throw gpu::Error("terrain: " + std::to_string(crowd.terrain().heights().size()) +
                         " heights, but the renderer was made with room for " + std::to_string(capacity_) +
                         " (RendererSettings::terrainSamples)");
}

void TerrainBuffer::recordUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, bool resend) {
    gpu::destroyBuffer(context_, staging_[frameSlot]);  // the slot's last frame is done with it
    if (crowd.terrainVersion() == uploadedVersion_ && !resend) return;
    uploadedVersion_ = crowd.terrainVersion();
    grid_ = crowd.terrain().grid();
    const std::vector<float>& heights = crowd.terrain().heights();
    if (heights.empty()) return;  // flat: the grid says so, the heights are not read
    staging_[frameSlot] = gpu::createBuffer(context_, heights.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                            gpu::MemoryUse::HostUpload, "terrain heights (upload)");
    std::memcpy(staging_[frameSlot].mapped, heights.data(), heights.size() * sizeof(float));
    // Every reader of the last frames (the motion pass, the ground) is done before the copy overwrites them.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                       {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkBufferCopy copy{0, 0, heights.size() * sizeof(float)};
    vkCmdCopyBuffer(cmd, staging_[frameSlot].buffer, heights_.buffer, 1, &copy);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
}

}  // namespace render
