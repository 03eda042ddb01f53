#pragma once
// Where pass 1 puts each (character, vertex) texel, within the device's image-size limits.
//
// Layout: one character owns `rowsPerCharacter` consecutive rows of a target; its vertices run
// left to right along them. The paper instead gives each row one vertex index (so a row reuses
// one vertex's data for every character). We keep characters in rows because the row-major
// image-to-buffer copy then yields a character-major vertex buffer: pass 2 draws character c with
// the model's unmodified index buffer and vertexOffset = c * characterStride. With the paper's
// layout the vertices of one character are strided across the buffer, which an index buffer with
// a plain offset cannot address. Either way a fragment tile of the rasterizer covers a few
// characters times a few vertices, so caches see the same reuse of bones and bind-pose data.
// Crowds taller than the device's largest image are split into several targets (tiles).
#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu_types.h"

namespace gpu { class VulkanContext; }

namespace skin {

struct SkinTargetLayout {
    std::uint32_t vertexCount = 0;
    std::uint32_t characterCount = 0;
    std::uint32_t width = 0;             // texels per row
    std::uint32_t rowsPerCharacter = 0;
    std::uint32_t charactersPerTile = 0;
    std::uint32_t tileCount = 0;

    // Vertices from one character's first vertex to the next's in the copied buffer (>= vertexCount).
    std::uint32_t characterStride() const { return width * rowsPerCharacter; }
    std::uint32_t firstCharacter(std::uint32_t tile) const { return tile * charactersPerTile; }
    std::uint32_t charactersInTile(std::uint32_t tile) const;
    VkExtent2D tileExtent(std::uint32_t tile) const;
};

// Plans the targets for a crowd; maxDimension is the device's largest image and framebuffer side.
SkinTargetLayout planSkinTargets(std::uint32_t vertexCount, std::uint32_t characterCount, std::uint32_t maxDimension);

// Push constants of pass 1 for one tile of the layout.
gpu::SkinPassParams skinPassParams(const SkinTargetLayout& layout, std::uint32_t tile, std::uint32_t boneStride);

// The largest skinning target side the device supports (image and framebuffer limits).
std::uint32_t maxSkinTargetDimension(const gpu::VulkanContext& context, std::uint32_t requested);

}  // namespace skin
