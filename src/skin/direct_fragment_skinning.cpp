#include "skin/direct_fragment_skinning.h"

#include "gpu/gpu_timer.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "skin_direct.frag.spv.h"
#include "skin_fragment.vert.spv.h"

namespace skin {
namespace {

SkinTargetLayout planFor(const MethodSetup& setup) {
    if (!setup.context.fragmentStores)
        throw gpu::Error("two-pass-direct needs fragmentStoresAndAtomics, which " + setup.context.description.name +
                         " lacks");
    return planSkinTargets(setup.crowd.vertexCount(), setup.crowd.characterCount(),
                           maxSkinTargetDimension(setup.context, setup.maxTargetDimension));
}


}  // namespace

DirectFragmentSkinning::DirectFragmentSkinning(const MethodSetup& setup)
    : context_(setup.context),
      crowd_(setup.crowd),
      layout_(planFor(setup)),
      skinned_(context_, layout_.characterCount, layout_.characterStride(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      descriptors_(context_, VK_SHADER_STAGE_FRAGMENT_BIT, skinningBindings(crowd_, skinned_)),
      draw_(setup, layout_.characterStride()) {
    const VkDescriptorSetLayout setLayout = descriptors_.layout();
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(gpu::SkinPassParams)};
    pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout, 1}, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = skin_fragment_vert_spv;
    desc.fragmentShader = skin_direct_frag_spv;
    desc.layout = pipelineLayout_;
    desc.cullMode = VK_CULL_MODE_NONE;
    pipeline_ = gpu::createGraphicsPipeline(context_, desc);
}

DirectFragmentSkinning::~DirectFragmentSkinning() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
}

void DirectFragmentSkinning::recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) {
    const gpu::Access fragmentWrite{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    skinned_.barrierBeforeWrite(cmd, fragmentWrite);
    for (std::uint32_t t = 0; t < layout_.tileCount; ++t) {
        // No attachments: the render area alone sets which fragments run.
        const VkExtent2D extent = layout_.tileExtent(t);
        VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        info.renderArea = {{0, 0}, extent};
        info.layerCount = 1;
        vkCmdBeginRendering(cmd, &info);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        const VkDescriptorSet set = descriptors_.set();
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
        gpu::setViewportAndScissor(cmd, extent);
        const gpu::SkinPassParams params = skinPassParams(layout_, t, crowd_.boneStride());
        vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof params, &params);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    skinned_.barrierAfterWrite(cmd, fragmentWrite);
    timer.mark(cmd, "skin");
}

void DirectFragmentSkinning::recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) {
    draw_.record(cmd, sceneSet, push, skinned_.vertices());
}

std::vector<MemoryItem> DirectFragmentSkinning::memory() const {
    return {{"skinned vertex buffer", skinned_.bytes()}, {"draw commands", draw_.indirectBytes()}};
}

}  // namespace skin
