#include "skin/vertex_shader_skinning.h"

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "skin/instanced_vertex_skinning.h"
#include "skin_vs.vert.spv.h"

namespace skin {
namespace {

// One character's bone block, bound at a different dynamic offset for every draw.
gpu::BufferBinding characterBonesBinding(const gpu::VulkanContext& context, const render::CrowdBuffers& crowd) {
    const VkDeviceSize range = static_cast<VkDeviceSize>(crowd.boneStride()) * sizeof(gpu::BoneRows);
    if (range > context.properties.limits.maxUniformBufferRange)
        throw gpu::Error("vs: " + std::to_string(crowd.jointCount()) + " joints need a " + gpu::formatBytes(range) +
                         " uniform range per draw, over this device's limit of " +
                         gpu::formatBytes(context.properties.limits.maxUniformBufferRange));
    return {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, crowd.bones().buffer, 0, range};
}

}  // namespace

VertexShaderSkinning::VertexShaderSkinning(const MethodSetup& setup)
    : context_(setup.context),
      crowd_(setup.crowd),
      bones_(context_, VK_SHADER_STAGE_VERTEX_BIT, {{characterBonesBinding(context_, crowd_)}}) {
    const VertexSkinningPipeline pipeline = createVertexSkinningPipeline(setup, skin_vs_vert_spv, bones_.layout());
    pipelineLayout_ = pipeline.layout;
    pipeline_ = pipeline.pipeline;
}

VertexShaderSkinning::~VertexShaderSkinning() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
}

void VertexShaderSkinning::recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &sceneSet, 0, nullptr);
    vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                       &push);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &crowd_.bindVertices().buffer, &offset);
    vkCmdBindIndexBuffer(cmd, crowd_.indices().buffer, 0, VK_INDEX_TYPE_UINT32);
    const std::uint32_t stride = crowd_.boneStride() * sizeof(gpu::BoneRows);
    const VkDescriptorSet bones = bones_.set();
    for (std::uint32_t c = 0; c < crowd_.characterCount(); ++c) {
        const std::uint32_t dynamicOffset = c * stride;
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 1, 1, &bones, 1, &dynamicOffset);
        vkCmdDrawIndexed(cmd, crowd_.indexCount(), 1, 0, 0, c);
    }
}

}  // namespace skin
