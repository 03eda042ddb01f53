#pragma once
// The paper's baseline: no skinning pass; the vertex shader skins the bind-pose mesh while drawing,
// one draw per character with that character's bones bound by a dynamic uniform-buffer offset
// (the Vulkan counterpart of loading the paper's constant registers before each draw).
#include <vector>

#include "gpu/descriptor_bundle.h"
#include "skin/skinning_method.h"

namespace skin {

class VertexShaderSkinning final : public SkinningMethod {
public:
    explicit VertexShaderSkinning(const MethodSetup& setup);
    ~VertexShaderSkinning() override;

    Method method() const override { return Method::VertexShader; }
    void recordSkinning(VkCommandBuffer, gpu::GpuTimer&) override {}
    void recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) override;
    std::vector<MemoryItem> memory() const override { return {}; }

private:
    const gpu::VulkanContext& context_;
    const render::CrowdBuffers& crowd_;
    gpu::DescriptorBundle bones_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace skin
