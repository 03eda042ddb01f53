#pragma once
// "vs-instanced", the modern baseline: vertex-shader skinning with the whole crowd in one instanced
// draw; each instance finds its character's bones in a storage buffer.
#include "gpu/descriptor_bundle.h"
#include "skin/skinning_method.h"

namespace skin {

class InstancedVertexSkinning final : public SkinningMethod {
public:
    explicit InstancedVertexSkinning(const MethodSetup& setup);
    ~InstancedVertexSkinning() override;

    Method method() const override { return Method::VertexShaderInstanced; }
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

// The pipeline both vertex-shader methods draw with: bind-pose vertices in, skinned and lit out.
// `vertexShader` differs in where it finds the bones; set 1 is `bonesLayout`.
struct VertexSkinningPipeline {
    VkPipelineLayout layout;
    VkPipeline pipeline;
};
VertexSkinningPipeline createVertexSkinningPipeline(const MethodSetup& setup, std::span<const std::uint32_t> vertexShader,
                                                    VkDescriptorSetLayout bonesLayout);

}  // namespace skin
