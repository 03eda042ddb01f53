#pragma once
// The full-screen resolve of a compute rasterizer's visibility buffer (docs/compute-raster.md): one
// triangle over the viewport inside the colour pass, whose fragment shader decodes the pixel's id,
// shades it and writes its depth, so the depth test merges it with the hardware-drawn characters.
#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

#include "render/target_format.h"

namespace gpu { class VulkanContext; }

namespace render {

// The resolve pipeline for `fragmentShader` (impostor_resolve.frag or mesh_resolve.frag) in `layout`.
VkPipeline createVisibilityResolve(const gpu::VulkanContext& context, std::span<const std::uint32_t> fragmentShader,
                                   VkPipelineLayout layout, const TargetFormat& target);

}  // namespace render
