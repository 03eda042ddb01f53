#include "skin/direct_fragment_skinning.h"

#include "gpu/pass_observer.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/draw_lists.h"
#include "skin_direct.frag.spv.h"

namespace skin {
namespace {

const MethodSetup& requireFragmentStores(const MethodSetup& setup) {
    if (!setup.context.fragmentStores)
        throw gpu::Error("two-pass-direct needs fragmentStoresAndAtomics, which " + setup.context.description.name +
                         " lacks");
    return setup;
}

}  // namespace

DirectFragmentSkinning::DirectFragmentSkinning(const MethodSetup& setup)
    : skinned_(std::make_unique<SkinnedVertexBuffer>(requireFragmentStores(setup).context, setup.lists.skinnedCapacity(),
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT)),
      pass_(std::make_unique<FragmentSkinPass>(setup, *skinned_, skin_direct_frag_spv, std::vector<VkFormat>{})) {}

void DirectFragmentSkinning::recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) {
    const gpu::Access fragmentWrite{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    skinned_->barrierBeforeWrite(cmd, fragmentWrite);
    const SkinTargetLayout& layout = pass_->layout();
    for (std::uint32_t t = 0; t < layout.tileCount; ++t) {
        // No attachments: the render area alone sets which fragments run.
        VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        info.renderArea = {{0, 0}, layout.tileExtent(t)};
        info.layerCount = 1;
        vkCmdBeginRendering(cmd, &info);
        pass_->recordTile(cmd, t);
        vkCmdEndRendering(cmd);
    }
    skinned_->barrierAfterWrite(cmd, fragmentWrite);
    gpu::passDone(passes, cmd, "skin");
}

}  // namespace skin
