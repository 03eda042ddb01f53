#pragma once
// The impostor level's draw: one vkCmdDrawIndexedIndirect whose instance count culling wrote (a quad
// per character of the frame's impostor list), textured from the atlas and lit like the meshes, inside the
// colour pass after the mesh draws. It reads records only: no bones, no skinned vertices.
#include <memory>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/impostor_atlas.h"
#include "render/scene_pass.h"

namespace gpu { class VulkanContext; }

namespace render {

class ImpostorDraw {
public:
    ImpostorDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                 const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout);
    ~ImpostorDraw();
    ImpostorDraw(const ImpostorDraw&) = delete;
    ImpostorDraw& operator=(const ImpostorDraw&) = delete;

    // Inside the colour pass (its viewport set), with the camera's scene set.
    void record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const ScenePush& push) const;

private:
    void release();

    const gpu::VulkanContext& context_;
    const DrawLists& lists_;
    const ImpostorAtlas& atlas_;
    std::unique_ptr<gpu::DescriptorBundle> set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
