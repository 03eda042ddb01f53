#pragma once
// "two-pass-direct": the paper's fragment pass, with each fragment storing its skinned vertex straight
// into pass 2's vertex buffer (a storage buffer) instead of an RGBA32F image: no image, no copy.
#include <memory>

#include "gpu/descriptor_bundle.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_draw.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class DirectFragmentSkinning final : public SkinningMethod {
public:
    explicit DirectFragmentSkinning(const MethodSetup& setup);
    ~DirectFragmentSkinning() override;

    Method method() const override { return Method::TwoPassDirect; }
    void recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) override;
    void recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) override;
    std::vector<MemoryItem> memory() const override;
    SkinnedVertices skinnedVertices() const override { return skinned_.vertices(); }

private:
    const gpu::VulkanContext& context_;
    const render::CrowdBuffers& crowd_;
    SkinTargetLayout layout_;
    SkinnedVertexBuffer skinned_;
    gpu::DescriptorBundle descriptors_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    SkinnedDraw draw_;
};

}  // namespace skin
