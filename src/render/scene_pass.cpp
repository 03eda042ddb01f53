#include "render/scene_pass.h"

#include <algorithm>
#include <cstring>

#include "ground.frag.spv.h"
#include "ground.vert.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/render_target.h"

namespace render {

ScenePass::ScenePass(const gpu::VulkanContext& context, std::uint32_t framesInFlight) : context_(context) {
    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    setLayout_ = gpu::createSetLayout(context, {&binding, 1});
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight};
    pool_ = gpu::createDescriptorPool(context, {&size, 1}, framesInFlight);
    for (std::uint32_t i = 0; i < framesInFlight; ++i) {
        uniforms_.push_back(gpu::createBuffer(context, sizeof(gpu::SceneUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                              gpu::MemoryUse::HostUpload, "scene uniforms"));
        sets_.push_back(gpu::allocateSet(context, pool_, setLayout_));
        gpu::writeBufferDescriptor(context, sets_.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                   uniforms_.back().buffer, 0, sizeof(gpu::SceneUniforms));
    }
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ScenePush)};
    groundLayout_ = gpu::createPipelineLayout(context, {&setLayout_, 1}, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = ground_vert_spv;
    desc.fragmentShader = ground_frag_spv;
    desc.colorFormats = {kColorFormat};
    desc.depthFormat = kDepthFormat;
    desc.layout = groundLayout_;
    desc.cullMode = VK_CULL_MODE_NONE;
    groundPipeline_ = gpu::createGraphicsPipeline(context, desc);
}

ScenePass::~ScenePass() {
    vkDestroyPipeline(context_.device, groundPipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, groundLayout_, nullptr);
    for (gpu::Buffer& b : uniforms_) gpu::destroyBuffer(context_, b);
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
}

void ScenePass::update(std::uint32_t frameSlot, const gpu::SceneUniforms& uniforms) {
    std::memcpy(uniforms_[frameSlot].mapped, &uniforms, sizeof uniforms);
}

void ScenePass::recordGround(VkCommandBuffer cmd, std::uint32_t frameSlot, const ScenePush& push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundPipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundLayout_, 0, 1, &sets_[frameSlot], 0, nullptr);
    vkCmdPushConstants(cmd, groundLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                       &push);
    vkCmdDraw(cmd, 6, 1, 0, 0);
}

gpu::SceneUniforms makeSceneUniforms(const glm::mat4& viewProjection, const std::vector<glm::vec4>& palette,
                                     float fogDensity) {
    gpu::SceneUniforms u{};
    u.viewProjection = viewProjection;
    u.lightDirection = glm::vec4(glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f)), 0.35f);
    u.skyColor = glm::vec4(kSkyColor, fogDensity);
    u.groundColor = glm::vec4(0.3f, 0.42f, 0.22f, 2.0f);
    for (std::size_t i = 0; i < std::min<std::size_t>(palette.size(), MAX_MATERIALS); ++i) u.palette[i] = palette[i];
    return u;
}

}  // namespace render
