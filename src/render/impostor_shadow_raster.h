#pragma once
// The impostor-level shadow casters rasterized in compute (issue 18, "the raster wall"), beside the
// mesh casters (render/shadow_raster.h) and into the same depth buffer. The hardware path draws each
// caster as a quad facing the light whose fragment shader cuts it by the atlas's coverage; seen from
// eye level inside a crowd, the shadow map's near cascade makes those quads hundreds of texels each,
// and on the H100 thousands of them cost the graphics slice over a millisecond a frame
// (docs/gpu-driven-frame.md). shaders/impostor_shadow_raster.comp.glsl draws the same quads, cells,
// coverage and depth on every SM.
#include <cstdint>
#include <memory>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"

namespace gpu { class VulkanContext; }

namespace render {

class CrowdBuffers;
class DrawLists;
class ImpostorAtlas;
struct ShadowCascades;

class ImpostorShadowRaster {
public:
    // `depth`: the shadow raster's buffer of depth bits (ShadowRaster::depthBits), `mapSize` its side.
    ImpostorShadowRaster(const gpu::VulkanContext& context, const CrowdBuffers& crowd, const DrawLists& lists,
                         const ImpostorAtlas& atlas, VkBuffer depth, std::uint32_t mapSize);
    ~ImpostorShadowRaster();
    ImpostorShadowRaster(const ImpostorShadowRaster&) = delete;
    ImpostorShadowRaster& operator=(const ImpostorShadowRaster&) = delete;

    // Outside any rendering pass, after the mesh casters' dispatch (ShadowRaster::rasterize) and before
    // the depths are packed (ShadowRaster::pack): this frame's impostor casters (culling's list).
    // `blend`: impostor-blend's coverage (two frames) or the nearest cell's.
    void record(VkCommandBuffer cmd, const ShadowCascades& cascades, bool blend);

private:
    void release();

    const gpu::VulkanContext& context_;
    const DrawLists& lists_;
    const ImpostorAtlas& atlas_;
    std::uint32_t mapSize_;
    gpu::Buffer frame_;  // the frame's light and map (ImpostorShadowFrame), written by the command buffer
    std::unique_ptr<gpu::DescriptorBundle> set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
