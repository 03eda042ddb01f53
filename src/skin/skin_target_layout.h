#pragma once
// Where pass 1 (the fragment-shader methods) puts each skinned vertex, within the device's
// image-size limits.
//
// Layout: skinned vertex slot g (the slot culling assigned, render/draw_lists.h) is texel
// g mod width of row g / width, counting rows across the targets in order. The paper gives each row
// one vertex index instead (so a row reuses one vertex's data for every character). We keep the
// slots in row-major order because the row-major image-to-buffer copy then yields exactly the dense,
// character-major vertex buffer that the draws address with vertexOffset; with the paper's layout
// one character's vertices are strided across the buffer, which an index buffer with a plain offset
// cannot address. A character's vertices run along a row and wrap to the next, so no texel is
// padding, whatever the LOD's vertex count. Either way a fragment tile of the rasterizer covers a
// few characters times a few vertices, so caches see the same reuse of bones and bind-pose data.
// Slots beyond one target's rows continue in the next target (tile).
#include <cstdint>

#include <vulkan/vulkan.h>

namespace gpu { class VulkanContext; }

namespace skin {

struct SkinTargetLayout {
    std::uint64_t capacity = 0;       // skinned vertex slots the targets hold
    std::uint32_t width = 0;          // texels per row
    std::uint32_t rowsPerTile = 0;    // rows of every target but the last
    std::uint32_t tileCount = 0;
    std::uint32_t totalRows = 0;

    std::uint32_t firstRow(std::uint32_t tile) const { return tile * rowsPerTile; }
    VkExtent2D tileExtent(std::uint32_t tile) const;
    // Both RGBA32F targets (positions, normals) of every tile.
    std::uint64_t bytes() const { return static_cast<std::uint64_t>(totalRows) * width * 2 * 16; }
};

// Rows this wide are long enough that few targets are needed and short enough that a bucket's
// region, which starts and ends mid-row, wastes little of its first and last rows.
inline constexpr std::uint32_t kPreferredTargetWidth = 1024;

// Plans the targets for `capacity` slots; maxDimension is the device's largest image and
// framebuffer side. Throws gpu::Error for a zero capacity or dimension.
SkinTargetLayout planSkinTargets(std::uint64_t capacity, std::uint32_t maxDimension);

// The largest skinning target side the device supports (image and framebuffer limits).
std::uint32_t maxSkinTargetDimension(const gpu::VulkanContext& context, std::uint32_t requested);

}  // namespace skin
