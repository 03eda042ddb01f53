#pragma once
// The paper's two-pass method. Pass 1 skins every (character, vertex) in a fragment shader into
// RGBA32F position and normal targets; vkCmdCopyImageToBuffer turns them into a vertex buffer;
// pass 2 (SkinnedDraw) draws it with the model's index buffer.
#include <memory>
#include <vector>

#include "gpu/descriptor_bundle.h"
#include "gpu/image.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_draw.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class FragmentSkinning final : public SkinningMethod {
public:
    explicit FragmentSkinning(const MethodSetup& setup);
    ~FragmentSkinning() override;

    Method method() const override { return Method::TwoPass; }
    void recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) override;
    void recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) override;
    std::vector<MemoryItem> memory() const override;
    SkinnedVertices skinnedVertices() const override;
    const SkinTargetLayout& layout() const { return layout_; }

private:
    struct Tile {
        gpu::Image position;
        gpu::Image normal;
    };
    void createPipeline();
    void recordTile(VkCommandBuffer cmd, std::uint32_t tile);
    void recordCopies(VkCommandBuffer cmd);
    void release();

    const gpu::VulkanContext& context_;
    const render::CrowdBuffers& crowd_;
    SkinTargetLayout layout_;
    std::vector<Tile> tiles_;
    std::unique_ptr<SkinnedVertexBuffer> skinned_;
    std::unique_ptr<gpu::DescriptorBundle> descriptors_;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::unique_ptr<SkinnedDraw> draw_;
};

}  // namespace skin
