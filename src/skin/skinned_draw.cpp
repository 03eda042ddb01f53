#include "skin/skinned_draw.h"

#include <vector>

#include "draw.frag.spv.h"
#include "draw.vert.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/crowd_buffers.h"
#include "render/render_target.h"

namespace skin {

SkinnedDraw::SkinnedDraw(const MethodSetup& setup, std::uint32_t characterStride)
    : context_(setup.context), crowd_(setup.crowd) {
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof(render::ScenePush)};
    layout_ = gpu::createPipelineLayout(context_, {&setup.sceneSetLayout, 1}, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = draw_vert_spv;
    desc.fragmentShader = draw_frag_spv;
    // Positions and normals are two streams of the same buffer (one image copied into each).
    desc.bindings = {{0, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    desc.colorFormats = {render::kColorFormat};
    desc.depthFormat = render::kDepthFormat;
    desc.layout = layout_;
    pipeline_ = gpu::createGraphicsPipeline(context_, desc);

    // One indexed draw per character; firstInstance carries the character index to the shaders.
    std::vector<VkDrawIndexedIndirectCommand> draws(crowd_.characterCount());
    for (std::uint32_t c = 0; c < draws.size(); ++c)
        draws[c] = {crowd_.indexCount(), 1, 0, static_cast<std::int32_t>(c * characterStride), c};
    indirect_ = gpu::createBufferWithData(context_, std::as_bytes(std::span(draws)),
                                          VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "draw commands");
}

SkinnedDraw::~SkinnedDraw() {
    gpu::destroyBuffer(context_, indirect_);
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, layout_, nullptr);
}

void SkinnedDraw::record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push,
                         const SkinnedVertices& vertices) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &sceneSet, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
    const VkBuffer buffers[2] = {vertices.buffer->buffer, vertices.buffer->buffer};
    const VkDeviceSize offsets[2] = {0, vertices.normalsOffset};
    vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
    vkCmdBindIndexBuffer(cmd, crowd_.indices().buffer, 0, VK_INDEX_TYPE_UINT32);
    const std::uint32_t count = crowd_.characterCount();
    if (context_.multiDrawIndirect) {
        vkCmdDrawIndexedIndirect(cmd, indirect_.buffer, 0, count, sizeof(VkDrawIndexedIndirectCommand));
    } else {
        for (std::uint32_t c = 0; c < count; ++c)
            vkCmdDrawIndexedIndirect(cmd, indirect_.buffer, c * sizeof(VkDrawIndexedIndirectCommand), 1,
                                     sizeof(VkDrawIndexedIndirectCommand));
    }
}

}  // namespace skin
