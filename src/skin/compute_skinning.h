#pragma once
// "compute": skinning in a compute shader straight into the draw pass's vertex buffer (no image, no
// copy), one indirect dispatch per (model, LOD) bucket over the characters culling kept.
// Every::CharacterOnce is the "static" ceiling: on its first frame it skins every character at every
// LOD into its own slot, then never again, so the frame is culling and drawing alone and every
// method's skinning cost is a ratio in the same run.
#include <memory>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class ComputeSkinning final : public SkinningMethod {
public:
    enum class Every { Frame, CharacterOnce };
    ComputeSkinning(const MethodSetup& setup, Every every);
    ~ComputeSkinning() override;

    Method method() const override { return once() ? Method::Static : Method::Compute; }
    void recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) override;
    std::vector<MemoryItem> memory() const override;
    render::SkinnedVertices skinnedVertices() const override { return skinned_->vertices(); }
    bool needsAnimation() const override { return !(once() && skinnedOnce_); }
    void invalidateSkinning() override { skinnedOnce_ = false; }
    bool fixedLayout() const override { return once(); }

private:
    bool once() const { return every_ == Every::CharacterOnce; }
    void recordDispatches(VkCommandBuffer cmd);
    void release();

    const gpu::VulkanContext& context_;
    const render::DrawLists& lists_;
    Every every_;
    bool skinnedOnce_ = false;
    std::unique_ptr<SkinnedVertexBuffer> skinned_;
    gpu::Buffer everyCharacter_;  // the fixed layout's list: every character of each bucket's model
    std::unique_ptr<gpu::DescriptorBundle> descriptors_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    // Per model (its joint count and characters per group), two: [2m] for its last level, [2m + 1]
    // with the morph into a coarser level (shaders/skin.comp.glsl, MORPHS).
    std::vector<VkPipeline> pipelines_;
};

}  // namespace skin
