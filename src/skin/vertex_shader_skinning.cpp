#include "skin/vertex_shader_skinning.h"

#include "draw.frag.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "render/render_target.h"
#include "skin_vs.vert.spv.h"

namespace skin {

VertexShaderSkinning::VertexShaderSkinning(const MethodSetup& setup) : context_(setup.context), crowd_(setup.crowd) {
    const VkDeviceSize range = static_cast<VkDeviceSize>(crowd_.boneStride()) * sizeof(gpu::BoneRows);
    if (range > context_.properties.limits.maxUniformBufferRange)
        throw gpu::Error("vs: " + std::to_string(crowd_.jointCount()) + " joints need a " + gpu::formatBytes(range) +
                         " uniform range per draw, over this device's limit of " +
                         gpu::formatBytes(context_.properties.limits.maxUniformBufferRange));
    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
                                               VK_SHADER_STAGE_VERTEX_BIT, nullptr};
    setLayout_ = gpu::createSetLayout(context_, {&binding, 1});
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1};
    pool_ = gpu::createDescriptorPool(context_, {&size, 1}, 1);
    set_ = gpu::allocateSet(context_, pool_, setLayout_);
    gpu::writeBufferDescriptor(context_, set_, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, crowd_.bones().buffer, 0,
                               range);

    const VkDescriptorSetLayout sets[2] = {setup.sceneSetLayout, setLayout_};
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof(render::ScenePush)};
    pipelineLayout_ = gpu::createPipelineLayout(context_, sets, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = skin_vs_vert_spv;
    desc.fragmentShader = draw_frag_spv;
    desc.bindings = {{0, sizeof(gpu::SkinVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, position)},
                       {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, normal)},
                       {2, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(gpu::SkinVertex, joints)},
                       {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, weights)}};
    desc.colorFormats = {render::kColorFormat};
    desc.depthFormat = render::kDepthFormat;
    desc.layout = pipelineLayout_;
    desc.vertexConstants = {crowd_.boneStride()};
    pipeline_ = gpu::createGraphicsPipeline(context_, desc);
}

VertexShaderSkinning::~VertexShaderSkinning() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
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
    for (std::uint32_t c = 0; c < crowd_.characterCount(); ++c) {
        const std::uint32_t dynamicOffset = c * stride;
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 1, 1, &set_, 1, &dynamicOffset);
        vkCmdDrawIndexed(cmd, crowd_.indexCount(), 1, 0, 0, c);
    }
}

}  // namespace skin
