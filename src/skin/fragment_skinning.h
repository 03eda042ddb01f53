#pragma once
// The paper's two-pass method. Pass 1 skins every visible (character, vertex) in a fragment shader
// into RGBA32F position and normal targets; vkCmdCopyImageToBuffer turns them into the vertex buffer
// the draw pass binds.
//
// The copy is sized conservatively: vkCmdCopyImageToBuffer has no indirect form, and only the GPU
// knows this frame's visible count, so every frame copies the whole targets (every character at
// LOD 0), while pass 1 shades only the visible characters' texels.
#include <memory>
#include <vector>

#include "gpu/image.h"
#include "skin/fragment_skin_pass.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class FragmentSkinning final : public SkinningMethod {
public:
    explicit FragmentSkinning(const MethodSetup& setup);
    ~FragmentSkinning() override;

    Method method() const override { return Method::TwoPass; }
    void recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) override;
    std::vector<MemoryItem> memory() const override;
    render::SkinnedVertices skinnedVertices() const override { return skinned_->vertices(); }
    const SkinTargetLayout& layout() const { return pass_->layout(); }

private:
    struct Tile {
        gpu::Image position;
        gpu::Image normal;
    };
    void recordTile(VkCommandBuffer cmd, std::uint32_t tile);
    void recordCopies(VkCommandBuffer cmd);
    void release();

    const gpu::VulkanContext& context_;
    std::unique_ptr<SkinnedVertexBuffer> skinned_;
    std::unique_ptr<FragmentSkinPass> pass_;
    std::vector<Tile> tiles_;
};

}  // namespace skin
