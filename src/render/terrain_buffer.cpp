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

std::uint64_t TerrainBuffer::bytesFor(const crowd::Crowd& crowd, std::uint32_t asked) {
    return sizeof(gpu::TerrainGrid) + std::uint64_t{samplesFor(crowd, asked)} * sizeof(float);
}

TerrainBuffer::TerrainBuffer(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t samples,
                             std::uint32_t framesInFlight)
    : context_(context), capacity_(samplesFor(crowd, samples)), staging_(framesInFlight) {
    // Zeros until the first upload: a grid of extent z = 0, flat.
    const std::vector<std::byte> zeros(sizeof(gpu::TerrainGrid) + std::size_t{capacity_} * sizeof(float));  // bytesFor
    buffer_ = gpu::createBufferWithData(context, zeros, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        "terrain");
    grid_ = crowd::Terrain().grid();
}

TerrainBuffer::~TerrainBuffer() {
    for (gpu::Buffer& b : staging_) gpu::destroyBuffer(context_, b);
    gpu::destroyBuffer(context_, buffer_);
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
    const std::vector<float>& heights = crowd.terrain().heights();  // none when flat: the grid says so
    const std::size_t bytes = sizeof grid_ + heights.size() * sizeof(float);
    staging_[frameSlot] = gpu::createBuffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::HostUpload,
                                            "terrain (upload)");
    auto* mapped = static_cast<std::byte*>(staging_[frameSlot].mapped);
    std::memcpy(mapped, &grid_, sizeof grid_);
    if (!heights.empty()) std::memcpy(mapped + sizeof grid_, heights.data(), heights.size() * sizeof(float));
    // Every reader of the last frames (the motion pass, the ground) is done before the copy overwrites them.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                       {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging_[frameSlot].buffer, buffer_.buffer, 1, &copy);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
}

}  // namespace render
