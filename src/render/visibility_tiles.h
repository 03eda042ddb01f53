#pragma once
// The screen tiles a compute rasterizer drew into (docs/compute-raster.md, "The resolve over covered
// tiles"). After rasterizing, a scan pass reads the slot's visibility buffer once, a workgroup a tile,
// and lists every tile holding a drawn pixel behind a VkDrawIndirectCommand (gpu::VisibilityTileList);
// the resolve then draws those tiles only, so the fragment work follows what was drawn, not the screen.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"

namespace gpu { class VulkanContext; }

namespace render {

// The tile side the resolves use (pixels); docs/compute-raster.md gives the measurements behind it.
constexpr std::uint32_t kResolveTilePixels = 16;
// Tile sides the scan takes: multiples of its workgroup's side (VISIBILITY_TILE_GROUP) up to 256.
bool isResolveTileSide(std::uint32_t pixels);

class VisibilityTiles {
public:
    // Lists for `framesInFlight` slots, tiles `tilePixels` a side (isResolveTileSide, else gpu::Error).
    VisibilityTiles(const gpu::VulkanContext& context, std::uint32_t framesInFlight, std::uint32_t tilePixels);
    ~VisibilityTiles();
    VisibilityTiles(const VisibilityTiles&) = delete;
    VisibilityTiles& operator=(const VisibilityTiles&) = delete;

    // Outside any render pass, after the rasterizer's last (compute) write to `visibility`, `extent`
    // pixels: lists the slot's covered tiles (the list made to the extent when it changes: the host has
    // waited for the slot's previous frame).
    void record(VkCommandBuffer cmd, std::uint32_t slot, const gpu::Buffer& visibility, VkExtent2D extent);
    // Inside the colour pass, a resolve pipeline taking the tiles as its instance attribute bound: draws
    // the slot's listed tiles.
    void recordDraw(VkCommandBuffer cmd, std::uint32_t slot) const;

    std::uint32_t tilePixels() const { return tilePixels_; }
    // gpu::VisibilityTileList, then the tiles (tests).
    const gpu::Buffer& list(std::uint32_t slot) const { return slots_[slot].list; }
    std::uint64_t bytes() const;

private:
    struct Slot {
        gpu::Buffer list;
        VkExtent2D extent{0, 0};
        VkBuffer visibility = VK_NULL_HANDLE;  // what the set binds
        std::unique_ptr<gpu::DescriptorBundle> set;
    };
    void makeSlot(std::uint32_t slot, const gpu::Buffer& visibility, VkExtent2D extent);
    void release();

    const gpu::VulkanContext& context_;
    std::uint32_t tilePixels_;
    std::vector<Slot> slots_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
