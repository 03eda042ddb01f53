#pragma once
// The resolve of a compute rasterizer's visibility buffer (docs/compute-raster.md), shared by the
// impostor and mesh rasterizers: inside the colour pass, a fragment shader (impostor_resolve.frag or
// mesh_resolve.frag) decodes each covered pixel's id, shades it and writes its depth, so the depth test
// merges it with the hardware-drawn characters. It runs over the screen tiles the rasterizer drew into
// (render/visibility_tiles.h: a scan lists them, an indirect draw covers them), or, for tests' and
// measurements' reference, over the whole viewport (one triangle).
#include <cstdint>
#include <memory>
#include <span>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "render/target_format.h"
#include "render/visibility_tiles.h"

namespace gpu { class VulkanContext; }

namespace render {

// The stages of the resolve pipelines' push constants: the tiles' vertex shader reads the viewport
// that both fragment shaders' push constants hold at byte 16 (offset xy, extent zw).
constexpr VkShaderStageFlags kResolvePushStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// How the resolve's fragments meet the target: opaque (colour and depth written, as a drawn
// character's), or a layer over it (colour blended by the fragment's alpha, depth tested, not written).
enum class ResolveWrite { Opaque, LayerOver };

// Device bytes of a visibility buffer for `extent`: one 64-bit word a pixel.
std::uint64_t visibilityBytes(VkExtent2D extent);
// Whether that buffer fits one storage binding on a device with these limits: the compute rasterizers
// bind it whole. Every Vulkan device allows 128 MiB, 4096 x 4096 pixels; a larger viewport on a device
// with no more stays with the hardware rasterizer.
bool visibilityFits(const VkPhysicalDeviceLimits& limits, VkExtent2D extent);

class VisibilityResolve {
public:
    // The resolve pipeline for `fragmentShader` in `layout` (push constants at kResolvePushStages).
    // `tilePixels`: the tiles' side (isResolveTileSide); 0 draws every pixel of the viewport.
    VisibilityResolve(const gpu::VulkanContext& context, std::span<const std::uint32_t> fragmentShader,
                      VkPipelineLayout layout, const TargetFormat& target, std::uint32_t framesInFlight,
                      std::uint32_t tilePixels, ResolveWrite write = ResolveWrite::Opaque);
    ~VisibilityResolve();
    VisibilityResolve(const VisibilityResolve&) = delete;
    VisibilityResolve& operator=(const VisibilityResolve&) = delete;

    // Outside any render pass, after the rasterizer's last write to the slot's visibility buffer: lists
    // its covered tiles (nothing to do over the whole viewport).
    void recordTiles(VkCommandBuffer cmd, std::uint32_t slot, const gpu::Buffer& visibility, VkExtent2D extent);
    // Inside the colour pass: binds the pipeline (then the caller binds its sets and pushes its constants).
    void bind(VkCommandBuffer cmd) const;
    // Draws the slot's resolve: its covered tiles, or the viewport.
    void draw(VkCommandBuffer cmd, std::uint32_t slot) const;

    // The tile lists (tests), null over the whole viewport.
    const VisibilityTiles* tiles() const { return tiles_.get(); }
    std::uint64_t bytes() const { return tiles_ ? tiles_->bytes() : 0; }

private:
    const gpu::VulkanContext& context_;
    std::unique_ptr<VisibilityTiles> tiles_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
