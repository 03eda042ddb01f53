#include "render/character_draw.h"

#include <iterator>
#include <string>

#include "draw.frag.spv.h"
#include "draw.vert.spv.h"
#include "render/shadow_map.h"
#include "shadow.frag.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "skin_vs.vert.spv.h"
#include "skin_vs_instanced.vert.spv.h"

namespace render {
namespace {

constexpr VkShaderStageFlags kDrawStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
// The bones' binding in the crowd set (shaders/crowd_set.glsl.inc).
constexpr std::uint32_t kCrowdSetBonesBinding = 3;

// The paper's baseline binds one character's bones per draw: a uniform range of the largest block.
gpu::BufferBinding boneBlockBinding(const gpu::VulkanContext& context, const CrowdBuffers& crowd) {
    const VkDeviceSize range = static_cast<VkDeviceSize>(crowd.largestBoneBlock()) * sizeof(gpu::BoneRows);
    if (range > context.properties.limits.maxUniformBufferRange)
        throw gpu::Error("vs: a bone block of " + gpu::formatBytes(range) + " is over this device's uniform range of " +
                         gpu::formatBytes(context.properties.limits.maxUniformBufferRange));
    return {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, crowd.bones().buffer, 0, range};
}

}  // namespace

CharacterDraw::CharacterDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                             const DrawLists& lists, VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target)
    : context_(context), pool_(pool), crowd_(crowd), lists_(lists) {
    try {
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding crowdBindings[] = {{storage, pool.modelTable().buffer},
                                                    {storage, crowd.characters().buffer},
                                                    {storage, lists.visible().buffer},
                                                    {storage, crowd.bones().buffer},
                                                    {storage, lists.shadowStates().buffer}};
        crowdSet_ = std::make_unique<gpu::DescriptorBundle>(context, kDrawStages, crowdBindings);
        const gpu::BufferBinding block[] = {boneBlockBinding(context, crowd)};
        boneBlock_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_VERTEX_BIT, block);
        createPipelines(sceneSetLayout, target);
    } catch (...) {
        release();
        throw;
    }
}

CharacterDraw::~CharacterDraw() { release(); }

void CharacterDraw::rebindBones() {
    crowdSet_->rebind(kCrowdSetBonesBinding, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd_.bones().buffer});
    boneBlock_->rebind(0, boneBlockBinding(context_, crowd_));
}

void CharacterDraw::release() {
    for (VkPipeline* pipelines : {colour_, shadow_})
        for (int i = 0; i < 3; ++i) {
            if (pipelines[i]) vkDestroyPipeline(context_.device, pipelines[i], nullptr);
            pipelines[i] = VK_NULL_HANDLE;
        }
    if (intoImpostor_) vkDestroyPipeline(context_.device, intoImpostor_, nullptr);
    intoImpostor_ = VK_NULL_HANDLE;
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
    boneBlock_.reset();
    crowdSet_.reset();
}

void CharacterDraw::createPipelines(VkDescriptorSetLayout sceneSetLayout, const TargetFormat& target) {
    const VkDescriptorSetLayout sets[3] = {sceneSetLayout, crowdSet_->layout(), boneBlock_->layout()};
    const VkPushConstantRange push{kDrawStages, 0, sizeof(ScenePush)};
    layout_ = gpu::createPipelineLayout(context_, sets, {&push, 1});
    gpu::GraphicsPipelineDesc colour;
    colour.fragmentShader = draw_frag_spv;
    colour.colorFormats = {target.color};
    colour.depthFormat = target.depth;
    colour.samples = target.samples;
    colour.layout = layout_;
    // A pool without textured materials draws with the variant that reads no texture coordinates
    // (draw.frag.glsl, kTextured).
    const std::uint32_t textured = pool_.texturedMaterials() != glm::uvec4(0u) ? 1u : 0u;
    colour.fragmentConstants = {0u, textured};
    createPipelines(colour, colour_);
    // Fades into impostors (from skinned vertices only): the character's mesh keeps the pixels the
    // impostor's complementary dither leaves (draw.frag.glsl, kDithered). Only it discards: the colour
    // list holds no instance of such a character (cull_emit.comp.glsl), so the colour pipeline above
    // keeps the early depth test for the rest. Fades between mesh levels need no pipeline of their
    // own: those characters are morphed while skinned (shaders/lod_morph.glsl.inc) and drawn whole.
    gpu::GraphicsPipelineDesc dithered = colour;
    dithered.vertexShader = draw_vert_spv;
    dithered.bindings = {{0, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}};
    dithered.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    dithered.fragmentConstants = {1u, textured};
    intoImpostor_ = gpu::createGraphicsPipeline(context_, dithered);
    // The shadow map: depth only, both faces (the light's projection is not mirrored like the camera's),
    // biased by slope so that lit surfaces do not shadow themselves.
    gpu::GraphicsPipelineDesc shadow = colour;
    shadow.fragmentShader = shadow_frag_spv;
    shadow.fragmentConstants = {};
    shadow.colorFormats = {};
    shadow.depthFormat = kShadowFormat;
    shadow.samples = VK_SAMPLE_COUNT_1_BIT;
    shadow.cullMode = VK_CULL_MODE_NONE;
    shadow.depthBiasConstant = 1.0f;
    shadow.depthBiasSlope = 1.5f;
    createPipelines(shadow, shadow_);
}

void CharacterDraw::createPipelines(gpu::GraphicsPipelineDesc desc, VkPipeline (&pipelines)[3]) {
    // Skinned vertices: positions and normals are two streams of the same buffer.
    desc.vertexShader = draw_vert_spv;
    desc.bindings = {{0, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    pipelines[static_cast<int>(DrawInput::SkinnedVertices)] = gpu::createGraphicsPipeline(context_, desc);

    // Bind-pose vertices, skinned while drawing.
    desc.bindings = {{0, sizeof(gpu::SkinVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, position)},
                       {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, normal)},
                       {2, 0, VK_FORMAT_R32G32B32A32_UINT, offsetof(gpu::SkinVertex, joints)},
                       {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(gpu::SkinVertex, weights)}};
    desc.vertexShader = skin_vs_vert_spv;
    desc.vertexConstants = {crowd_.largestBoneBlock()};
    pipelines[static_cast<int>(DrawInput::BindPosePerCharacter)] = gpu::createGraphicsPipeline(context_, desc);
    desc.vertexShader = skin_vs_instanced_vert_spv;
    desc.vertexConstants = {};
    pipelines[static_cast<int>(DrawInput::BindPoseInstanced)] = gpu::createGraphicsPipeline(context_, desc);
}

void CharacterDraw::bindCommon(VkCommandBuffer cmd, VkPipeline pipeline, VkDescriptorSet sceneSet,
                               const ScenePush& push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const VkDescriptorSet sets[2] = {sceneSet, crowdSet_->set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 2, sets, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, kDrawStages, 0, sizeof push, &push);
    vkCmdBindIndexBuffer(cmd, pool_.indices().buffer, 0, VK_INDEX_TYPE_UINT32);
}

void CharacterDraw::record(VkCommandBuffer cmd, DrawInput input, const SkinnedVertices& vertices,
                           VkDescriptorSet sceneSet, const ScenePush& push, Target target, bool fades) const {
    constexpr std::uint32_t stride = sizeof(gpu::DrawIndexedCommand);
    const VkDeviceSize zero = 0;
    const bool colour = target == Target::Colour;
    const bool faded = fades && colour && input == DrawInput::SkinnedVertices;
    const VkPipeline pipeline = (colour ? colour_ : shadow_)[static_cast<int>(input)];
    // The shadow pass's commands follow the colour pass's in each buffer (render/draw_lists.h).
    switch (input) {
        case DrawInput::SkinnedVertices: {
            bindCommon(cmd, pipeline, sceneSet, push);
            const VkBuffer buffers[2] = {vertices.buffer->buffer, vertices.buffer->buffer};
            const VkDeviceSize offsets[2] = {0, vertices.normalsOffset};
            vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
            vkCmdDrawIndexedIndirectCount(
                cmd, lists_.draws().buffer, colour ? 0 : VkDeviceSize{lists_.drawCapacity()} * stride,
                lists_.totals().buffer, colour ? offsetof(gpu::DrawTotals, drawCount) : offsetof(gpu::DrawTotals, shadowDrawCount),
                lists_.drawCapacity(), stride);
            if (faded) {
                // The characters fading into their impostors (no instance above): their mesh on its share
                // of their pixels; the impostor draws take the rest.
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, intoImpostor_);
                vkCmdDrawIndexedIndirectCount(cmd, lists_.draws().buffer, VkDeviceSize{lists_.fadingDrawBase()} * stride,
                                              lists_.totals().buffer, offsetof(gpu::DrawTotals, fading),
                                              lists_.drawCapacity(), stride);
            }
            break;
        }
        case DrawInput::BindPoseInstanced:
            bindCommon(cmd, pipeline, sceneSet, push);
            vkCmdBindVertexBuffers(cmd, 0, 1, &pool_.bindVertices().buffer, &zero);
            vkCmdDrawIndexedIndirect(cmd, lists_.bucketDraws().buffer,
                                     colour ? 0 : VkDeviceSize{lists_.bucketCount()} * stride, lists_.bucketCount(), stride);
            break;
        case DrawInput::BindPosePerCharacter: {
            bindCommon(cmd, pipeline, sceneSet, push);
            vkCmdBindVertexBuffers(cmd, 0, 1, &pool_.bindVertices().buffer, &zero);
            // The paper's shape: the CPU binds each character's bones and issues its draw; the GPU has
            // written each slot's command (instanceCount 0 when culled, its LOD's range otherwise).
            const VkDescriptorSet block = boneBlock_->set();
            const std::span<const std::uint32_t> offsets = crowd_.boneOffsets();
            const std::uint32_t first = colour ? 0u : crowd_.characterCount();
            for (std::uint32_t c = 0; c < crowd_.characterCount(); ++c) {
                const auto dynamicOffset = static_cast<std::uint32_t>(offsets[c] * sizeof(gpu::BoneRows));
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 2, 1, &block, 1, &dynamicOffset);
                vkCmdDrawIndexedIndirect(cmd, lists_.characterDraws().buffer,
                                         static_cast<VkDeviceSize>(first + c) * stride, 1, stride);
            }
            break;
        }
    }
}

}  // namespace render
