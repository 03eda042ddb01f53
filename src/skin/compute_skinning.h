#pragma once
// "compute": skinning in a compute shader straight into pass 2's vertex buffer (no image, no copy).
// With `once`, it skins only on the first frame and never again: the "static" ceiling, which draws
// the same crowd with no skinning work so every method's skinning cost is a ratio in the same run.
#include <memory>

#include "gpu/descriptor_bundle.h"
#include "skin/skinned_draw.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class ComputeSkinning final : public SkinningMethod {
public:
    ComputeSkinning(const MethodSetup& setup, bool once);
    ~ComputeSkinning() override;

    Method method() const override { return once_ ? Method::Static : Method::Compute; }
    void recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) override;
    void recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) override;
    std::vector<MemoryItem> memory() const override;
    SkinnedVertices skinnedVertices() const override { return skinned_.vertices(); }
    bool needsAnimation() const override { return !(once_ && skinnedOnce_); }

private:
    void recordDispatches(VkCommandBuffer cmd);

    const gpu::VulkanContext& context_;
    const render::CrowdBuffers& crowd_;
    bool once_;
    bool skinnedOnce_ = false;
    std::uint32_t charactersPerGroup_;
    SkinnedVertexBuffer skinned_;
    gpu::DescriptorBundle descriptors_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    SkinnedDraw draw_;
};

}  // namespace skin
