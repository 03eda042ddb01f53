#pragma once
// The impostor level's draw: indexed quads (four vertices each) for the characters of the frame's
// impostor list, in one draw per IMPOSTOR_QUADS_PER_DRAW of them whose count culling decides, textured
// from the atlas and lit like the meshes, inside the colour pass after the mesh draws. It reads records
// only: no bones, no skinned vertices. With shadows, the characters of the frame's casting impostor list
// are drawn into the shadow map as the same quads facing the light (docs/gpu-driven-frame.md, "Impostor
// shadows").
#include <memory>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/impostor_atlas.h"
#include "render/scene_pass.h"

#include "render/target_format.h"

namespace gpu { class VulkanContext; }

namespace render {

// With the compute rasterizer (render/impostor_raster.h), the colour pass draws only the impostors it
// left to the hardware: their count (ImpostorSplit) and list. Null: every impostor in view, as without
// it. The shadow pass always draws every casting impostor.
struct ImpostorSplitBuffers {
    const gpu::Buffer* count = nullptr;
    const gpu::Buffer* list = nullptr;
};

class ImpostorDraw {
public:
    ImpostorDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                 const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout,
                 const TargetFormat& target, ImpostorSplitBuffers split = {});
    ~ImpostorDraw();
    ImpostorDraw(const ImpostorDraw&) = delete;
    ImpostorDraw& operator=(const ImpostorDraw&) = delete;

    // Outside any render pass, after culling: this frame's draws, from culling's impostor count.
    void recordDraws(VkCommandBuffer cmd) const;
    // Inside the colour pass (its viewport set), with the camera's scene set. `blend`: four cells
    // blended (impostor_sample.glsl.inc), or the nearest cell alone (cheaper: one fetch a texture).
    void record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const ScenePush& push, bool blend = true) const;
    // Inside the shadow map's pass, with the light's scene set: the casting impostors' quads.
    void recordShadows(VkCommandBuffer cmd, VkDescriptorSet lightSet, const ScenePush& push, bool blend = true) const;
    // The fixed index buffer and the draw commands.
    std::uint64_t bytes() const { return quad_.size + draws_.size; }

private:
    void release();

    const gpu::VulkanContext& context_;
    const DrawLists& lists_;
    const ImpostorAtlas& atlas_;
    gpu::Buffer quad_;   // indices of IMPOSTOR_QUADS_PER_DRAW quads
    gpu::Buffer draws_;  // ImpostorDrawsHeader, then up to maxDraws_ indexed draws for each pass
    std::uint32_t maxDraws_ = 1;
    std::uint32_t characters_ = 0;
    std::unique_ptr<gpu::DescriptorBundle> set_, colourSet_, drawsSet_;  // colourSet_: the split's list
    VkPipelineLayout drawsLayout_ = VK_NULL_HANDLE;
    VkPipeline drawsPipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_[2] = {};        // by impostor blending: off (the nearest cell), on
    VkPipeline shadowPipeline_[2] = {};
};

}  // namespace render
