#pragma once
// The crowd's terrain on the GPU (crowd/terrain.h): its grid and then its heights in one storage buffer
// (TERRAIN_BUFFER, gpu_types.h) that the motion pass (where characters stand), the event pass and the
// ground (which is drawn as it) read. Sized when the renderer is made for the larger of the crowd's
// heightfield then and the samples the host asks room for; a terrain set later uploads at the next frame.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/buffer.h"

namespace gpu { class VulkanContext; }

namespace render {

class TerrainBuffer {
public:
    // Room for `samples` heights at least (and the crowd's terrain's).
    TerrainBuffer(const gpu::VulkanContext& context, const crowd::Crowd& crowd, std::uint32_t samples, std::uint32_t framesInFlight);
    ~TerrainBuffer();
    TerrainBuffer(const TerrainBuffer&) = delete;
    TerrainBuffer& operator=(const TerrainBuffer&) = delete;

    // The samples a renderer holds for a crowd and the host's ask, and the bytes of its buffer (the grid
    // and 4 bytes a sample; the memory planner's figure, without the uploads of a terrain set later).
    static std::uint32_t samplesFor(const crowd::Crowd& crowd, std::uint32_t asked);
    static std::uint64_t bytesFor(const crowd::Crowd& crowd, std::uint32_t asked);
    // Throws gpu::Error when the crowd's terrain has more heights than the buffer holds.
    void check(const crowd::Crowd& crowd) const;
    // Uploads the crowd's heights when they changed since the last upload, or always with `resend` (a
    // frame that carried them may never have run: render/frame_ledger.h). Before the motion pass.
    void recordUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, bool resend);
    // The grid of the heights uploaded last (no terrain: extent z = 0), as the CPU keeps it.
    const gpu::TerrainGrid& grid() const { return grid_; }
    // The grid, then the heights.
    const gpu::Buffer& buffer() const { return buffer_; }

private:
    const gpu::VulkanContext& context_;
    std::uint32_t capacity_;
    gpu::Buffer buffer_;
    std::vector<gpu::Buffer> staging_;  // per frame slot: its last upload's (freed when the slot comes round)
    gpu::TerrainGrid grid_{};
    std::uint64_t uploadedVersion_ = ~0ull;
};

}  // namespace render
