#include "skin/instanced_vertex_skinning.h"

#include "draw.frag.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/crowd_buffers.h"
#include "render/render_target.h"
#include "skin_vs_instanced.vert.spv.h"

namespace skin {

VertexSkinningPipeline createVertexSkinningPipeline(const MethodSetup& setup, std::span<const std::uint32_t> vertexShader,
                                                    VkDescriptorSetLayout bonesLayout) {
    const VkDescriptorSetLayout sets[2] = {setup.sceneSetLayout, bonesLayout};
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof(render::ScenePush)};
    VertexSkinningPipeline result{};
    result.layout = gpu::createPipelineLayout(setup.context, sets, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = vertexShader;
    desc.fragmentShader = draw_frag_spv;
    desc.bindings = {{0, sizeof(gpu::SkinVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, position)},
                       {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, normal)},
                       {2, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(gpu::SkinVertex, joints)},
                       {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, weights)}};
    desc.colorFormats = {render::kColorFormat};
    desc.depthFormat = render::kDepthFormat;
    desc.layout = result.layout;
    desc.vertexConstants = {setup.crowd.boneStride()};
    result.pipeline = gpu::createGraphicsPipeline(setup.context, desc);
    return result;
}

namespace {
gpu::BufferBinding boneBinding(const render::CrowdBuffers& crowd) {
    return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd.bones().buffer};
}
}  // namespace

InstancedVertexSkinning::InstancedVertexSkinning(const MethodSetup& setup)
    : context_(setup.context), crowd_(setup.crowd), bones_(context_, VK_SHADER_STAGE_VERTEX_BIT, {{boneBinding(crowd_)}}) {
    const VertexSkinningPipeline pipeline = createVertexSkinningPipeline(setup, skin_vs_instanced_vert_spv, bones_.layout());
    pipelineLayout_ = pipeline.layout;
    pipeline_ = pipeline.pipeline;
}

InstancedVertexSkinning::~InstancedVertexSkinning() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
}

void InstancedVertexSkinning::recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDescriptorSet sets[2] = {sceneSet, bones_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 2, sets, 0, nullptr);
    vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                       &push);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &crowd_.bindVertices().buffer, &offset);
    vkCmdBindIndexBuffer(cmd, crowd_.indices().buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, crowd_.indexCount(), crowd_.characterCount(), 0, 0, 0);
}

}  // namespace skin
