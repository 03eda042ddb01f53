#include "render/impostor_draw.h"

#include <cstddef>
#include <span>

#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "impostor.frag.spv.h"
#include "impostor.vert.spv.h"
#include "render/render_target.h"

namespace render {

namespace {
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
}

ImpostorDraw::ImpostorDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                           const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout)
    : context_(context), lists_(lists), atlas_(atlas) {
    try {
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding bindings[] = {{storage, pool.modelTable().buffer},
                                               {storage, atlas.modelTable().buffer},
                                               {storage, crowd.characters().buffer},
                                               {storage, lists.impostorList().buffer}};
        set_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_VERTEX_BIT, bindings);
        const VkDescriptorSetLayout sets[3] = {sceneSetLayout, set_->layout(), atlas.setLayout()};
        const VkPushConstantRange push{kStages, 0, sizeof(ScenePush)};
        layout_ = gpu::createPipelineLayout(context, sets, {&push, 1});
        gpu::GraphicsPipelineDesc desc;
        desc.vertexShader = impostor_vert_spv;
        desc.fragmentShader = impostor_frag_spv;
        desc.colorFormats = {kColorFormat};
        desc.depthFormat = kDepthFormat;
        desc.layout = layout_;
        desc.cullMode = VK_CULL_MODE_NONE;  // a quad facing the eye: its winding is not worth deriving
        pipeline_ = gpu::createGraphicsPipeline(context, desc);
    } catch (...) {
        release();
        throw;
    }
}

ImpostorDraw::~ImpostorDraw() { release(); }

void ImpostorDraw::release() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE, layout_ = VK_NULL_HANDLE;
    set_.reset();
}

void ImpostorDraw::record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const ScenePush& push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDescriptorSet sets[3] = {sceneSet, set_->set(), atlas_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 3, sets, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, kStages, 0, sizeof push, &push);
    // Six vertices per impostor in one draw, no index buffer. The Count form with a count of 1 rather
    // than vkCmdDrawIndirect: lavapipe (Mesa 22.3) kept the count buffer of the mesh draw before it and
    // drew nothing. Same cost on other devices.
    vkCmdDrawIndirectCount(cmd, lists_.impostorFrame().buffer, 0, lists_.impostorFrame().buffer,
                           offsetof(gpu::ImpostorFrame, drawCount), 1, sizeof(gpu::ImpostorFrame));
}

}  // namespace render
