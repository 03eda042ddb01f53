#include "render/scene_pass.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "ground.frag.spv.h"
#include "ground.vert.spv.h"
#include "sky.frag.spv.h"
#include "sky.vert.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/geometry_pool.h"
#include "render/ground_sunlight.h"
#include "render/shadow_map.h"
#include "render/terrain_buffer.h"

namespace render {

ScenePass::ScenePass(const gpu::VulkanContext& context, std::uint32_t framesInFlight, const GeometryPool& pool,
                     const ShadowMap& shadowMap, const GroundSunlight& groundSunlight, const TerrainBuffer& terrain,
                     const TargetFormat& target, GroundOptions ground)
    : context_(context), framesInFlight_(framesInFlight) {
    constexpr VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorSetLayoutBinding bindings[7] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both, nullptr},
        {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, MAX_TEXTURES, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, both, nullptr},
        {6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, both, nullptr}};  // the terrain's grid and heights
    setLayout_ = gpu::createSetLayout(context, bindings);
    // One set per frame in flight seen from the camera, then one per frame and shadow cascade seen from the light.
    const std::uint32_t sets = framesInFlight * (1 + kMostShadowCascades);
    const VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
                                           {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sets * (MAX_TEXTURES + 2)},
                                           {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * sets}};
    pool_ = gpu::createDescriptorPool(context, sizes, sets);
    for (std::uint32_t i = 0; i < sets; ++i) {
        uniforms_.push_back(gpu::createBuffer(context, sizeof(gpu::SceneUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                              gpu::MemoryUse::HostUpload, "scene uniforms"));
        sets_.push_back(gpu::allocateSet(context, pool_, setLayout_));
        gpu::writeBufferDescriptor(context, sets_.back(), 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                   uniforms_.back().buffer, 0, sizeof(gpu::SceneUniforms));
        writeTextures(sets_.back(), pool);
        gpu::writeBufferDescriptor(context, sets_.back(), 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                   pool.textureCoordinates().buffer, 0, VK_WHOLE_SIZE);
        gpu::writeBufferDescriptor(context, sets_.back(), 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, pool.materials().buffer, 0,
                                   VK_WHOLE_SIZE);
        gpu::writeBufferDescriptor(context, sets_.back(), 6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, terrain.buffer().buffer, 0,
                                   VK_WHOLE_SIZE);
        constexpr VkDescriptorType sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        constexpr VkImageLayout readOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        gpu::writeImageDescriptor(context, sets_.back(), 3, sampled, shadowMap.sampler(), shadowMap.view(), readOnly);
        gpu::writeImageDescriptor(context, sets_.back(), 4, sampled, groundSunlight.sampler(), groundSunlight.view(),
                                  readOnly);
    }
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ScenePush)};
    groundLayout_ = gpu::createPipelineLayout(context, {&setLayout_, 1}, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = ground_vert_spv;
    desc.fragmentShader = ground_frag_spv;
    desc.colorFormats = {target.color};
    desc.depthFormat = target.depth;
    desc.samples = target.samples;
    desc.fragmentConstants = {ground.filteredTiles ? 1u : 0u, ground.sunlightImage ? 1u : 0u};
    desc.layout = groundLayout_;
    desc.cullMode = VK_CULL_MODE_NONE;
    groundPipeline_ = gpu::createGraphicsPipeline(context, desc);
    gpu::GraphicsPipelineDesc sky = desc;  // the same target and layout
    sky.vertexShader = sky_vert_spv;
    sky.fragmentShader = sky_frag_spv;
    sky.fragmentConstants = {};
    sky.depthWrite = false;  // the depth stays 1 there, as cleared, for whatever the host draws after
    sky.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    skyPipeline_ = gpu::createGraphicsPipeline(context, sky);
}

ScenePass::~ScenePass() {
    vkDestroyPipeline(context_.device, skyPipeline_, nullptr);
    vkDestroyPipeline(context_.device, groundPipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, groundLayout_, nullptr);
    for (gpu::Buffer& b : uniforms_) gpu::destroyBuffer(context_, b);
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
}

void ScenePass::writeTextures(VkDescriptorSet set, const GeometryPool& pool) const {
    std::array<VkDescriptorImageInfo, MAX_TEXTURES> images;
    const std::array<VkImageView, MAX_TEXTURES> views = pool.textures().views();
    for (std::size_t i = 0; i < images.size(); ++i)
        images[i] = {pool.textures().sampler(), views[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = 1;
    write.descriptorCount = MAX_TEXTURES;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = images.data();
    vkUpdateDescriptorSets(context_.device, 1, &write, 0, nullptr);
}

void ScenePass::update(std::uint32_t frameSlot, const gpu::SceneUniforms& uniforms) {
    std::memcpy(uniforms_[frameSlot].mapped, &uniforms, sizeof uniforms);
}

void ScenePass::updateLight(std::uint32_t frameSlot, std::uint32_t cascade, const gpu::SceneUniforms& uniforms) {
    std::memcpy(uniforms_[lightIndex(frameSlot, cascade)].mapped, &uniforms, sizeof uniforms);
}

std::uint32_t groundVertices(const gpu::TerrainGrid& grid) {
    if (!(grid.extent.z > 0.0f)) return 6;  // one quad
    // As ground.vert.glsl lays them out: every stride-th line of the grid, and a ring out to the edge.
    auto inner = [](std::uint32_t samples) {
        const std::uint32_t stride = std::max(1u, (samples - 2u) / GROUND_MOST_CELLS + 1u);
        return (samples - 1u + stride - 1u) / stride;
    };
    return 6u * (inner(grid.size.x) + 2u) * (inner(grid.size.y) + 2u);
}

void ScenePass::recordGround(VkCommandBuffer cmd, std::uint32_t frameSlot, const ScenePush& push,
                             const gpu::TerrainGrid& terrain) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundPipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundLayout_, 0, 1, &sets_[frameSlot], 0, nullptr);
    vkCmdPushConstants(cmd, groundLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                       &push);
    vkCmdDraw(cmd, groundVertices(terrain), 1, 0, 0);
}

void ScenePass::recordSky(VkCommandBuffer cmd, std::uint32_t frameSlot) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, skyPipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, groundLayout_, 0, 1, &sets_[frameSlot], 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
}

gpu::SceneUniforms makeSceneUniforms(const glm::mat4& viewProjection, float fogDensity,
                                     const ShadowCascades& cascades, bool shadows, std::uint32_t shadowMapSize) {
    gpu::SceneUniforms u{};
    u.shadowLight = cascades.clip[0];
    for (std::uint32_t c = 0; c < kMostShadowCascades; ++c) {
        u.shadowFromFirst[c] = cascades.fromFirst[c];
        u.shadowSquares[c] = cascades.square[c];
    }
    u.shadowCascadeUse = glm::vec4(static_cast<float>(cascades.count), cascades.ownedWithin, 0.0f, 0.0f);
    u.shadowView = cascades.view;
    // Where each stretch but the last ends; past the used ones, never (the comparison stays false).
    for (std::uint32_t c = 0; c < kMostShadowCascades; ++c)
        u.shadowSplits[static_cast<int>(c)] = c + 1 < cascades.count ? cascades.splits[c + 1] : 1e30f;
    u.shadow = glm::vec4(shadows ? 1.0f : 0.0f, kShadowDepthBias, 1.0f / static_cast<float>(shadowMapSize), 0.0f);
    u.viewProjection = viewProjection;
    u.lightDirection = glm::vec4(lightDirection(), 0.35f);
    u.skyColor = glm::vec4(kSkyColor, fogDensity);
    u.groundColor = glm::vec4(0.3f, 0.42f, 0.22f, 2.0f);
    return u;
}

}  // namespace render
