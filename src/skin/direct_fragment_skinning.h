#pragma once
// "two-pass-direct": the paper's fragment pass, with each fragment storing its skinned vertex straight
// into the draw pass's vertex buffer (a storage buffer) instead of an RGBA32F image: no image, no copy.
#include <memory>

#include "skin/fragment_skin_pass.h"
#include "skin/skinned_vertex_buffer.h"
#include "skin/skinning_method.h"

namespace skin {

class DirectFragmentSkinning final : public SkinningMethod {
public:
    explicit DirectFragmentSkinning(const MethodSetup& setup);

    Method method() const override { return Method::TwoPassDirect; }
    void recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) override;
    std::vector<MemoryItem> memory() const override { return {{"skinned vertex buffer", skinned_->bytes()}}; }
    render::SkinnedVertices skinnedVertices() const override { return skinned_->vertices(); }

private:
    std::unique_ptr<SkinnedVertexBuffer> skinned_;
    std::unique_ptr<FragmentSkinPass> pass_;
};

}  // namespace skin
