#pragma once
// Pass 2 for every method that skins before drawing: draws each character from the skinned vertex
// buffer with the model's index buffer, all characters in one multi-draw-indirect call.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "render/scene_pass.h"
#include "skin/skinning_method.h"

namespace skin {

class SkinnedDraw {
public:
    // characterStride: vertices between consecutive characters in the skinned buffer.
    SkinnedDraw(const MethodSetup& setup, std::uint32_t characterStride);
    ~SkinnedDraw();
    SkinnedDraw(const SkinnedDraw&) = delete;
    SkinnedDraw& operator=(const SkinnedDraw&) = delete;

    void record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push,
                const SkinnedVertices& vertices) const;
    VkDeviceSize indirectBytes() const { return indirect_.size; }

private:
    const gpu::VulkanContext& context_;
    const render::CrowdBuffers& crowd_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    gpu::Buffer indirect_;
};

}  // namespace skin
