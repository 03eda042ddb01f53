#include "render/impostor_draw.h"

#include <algorithm>

#include <cstddef>
#include <span>
#include <vector>

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "impostor.frag.spv.h"
#include "impostor.vert.spv.h"
#include "impostor_draws.comp.spv.h"
#include "impostor_shadow.frag.spv.h"
#include "render/shadow_map.h"

namespace render {

namespace {
constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

struct DrawsPush {
    std::uint32_t maxDraws;
    std::uint32_t characters;
};
}  // namespace

ImpostorDraw::ImpostorDraw(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                           const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout,
                           const TargetFormat& target, ImpostorSplitBuffers split)
    : context_(context), lists_(lists), atlas_(atlas) {
    try {
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        // A fixed index buffer of IMPOSTOR_QUADS_PER_DRAW quads, whatever the crowd: (0, 1, 2), (0, 2, 3).
        std::vector<std::uint32_t> indices(std::size_t{IMPOSTOR_QUADS_PER_DRAW} * 6);
        for (std::uint32_t q = 0; q < IMPOSTOR_QUADS_PER_DRAW; ++q) {
            const std::uint32_t quad[6] = {4 * q, 4 * q + 1, 4 * q + 2, 4 * q, 4 * q + 2, 4 * q + 3};
            std::copy(quad, quad + 6, indices.begin() + static_cast<std::ptrdiff_t>(6 * q));
        }
        quad_ = gpu::createBufferWithData(context, std::as_bytes(std::span(indices)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                          "impostor quad indices");
        characters_ = lists.characterCount();
        maxDraws_ = std::max((characters_ + IMPOSTOR_QUADS_PER_DRAW - 1) / IMPOSTOR_QUADS_PER_DRAW, 1u);
        draws_ = gpu::createBuffer(context,
                                   sizeof(gpu::ImpostorDrawsHeader) + 2 * maxDraws_ * sizeof(gpu::DrawIndexedCommand),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                   gpu::MemoryUse::DeviceLocal, "impostor draws");
        // Binding 2, the colour pass's count: ImpostorFrame::count or ImpostorSplit::hardwareCount (both first).
        const gpu::BufferBinding drawBindings[] = {{storage, lists.impostorFrame().buffer},
                                                   {storage, draws_.buffer},
                                                   {storage, split.count ? split.count->buffer : lists.impostorFrame().buffer}};
        drawsSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, drawBindings);
        const VkDescriptorSetLayout drawsSetLayout = drawsSet_->layout();
        const VkPushConstantRange drawsPush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(DrawsPush)};
        drawsLayout_ = gpu::createPipelineLayout(context, {&drawsSetLayout, 1}, {&drawsPush, 1});
        drawsPipeline_ = gpu::createComputePipeline(context, impostor_draws_comp_spv, drawsLayout_, {});
        const gpu::BufferBinding bindings[] = {{storage, pool.modelTable().buffer},
                                               {storage, atlas.modelTable().buffer},
                                               {storage, crowd.characters().buffer},
                                               {storage, lists.impostorList().buffer},
                                               {storage, lists.shadowStates().buffer}};
        set_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_VERTEX_BIT, bindings);
        if (split.list) {
            const gpu::BufferBinding colour[] = {bindings[0], bindings[1], bindings[2], {storage, split.list->buffer},
                                                 bindings[4]};
            colourSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_VERTEX_BIT, colour);
        }
        const VkDescriptorSetLayout sets[3] = {sceneSetLayout, set_->layout(), atlas.setLayout()};
        const VkPushConstantRange push{kStages, 0, sizeof(ScenePush)};
        layout_ = gpu::createPipelineLayout(context, sets, {&push, 1});
        gpu::GraphicsPipelineDesc desc;
        desc.vertexShader = impostor_vert_spv;
        desc.fragmentShader = impostor_frag_spv;
        desc.colorFormats = {target.color};
        desc.depthFormat = target.depth;
        desc.samples = target.samples;
        // Multisampled, a texel's coverage in the atlas becomes the share of the pixel's samples it
        // covers (as a mesh's edge does), with no sorting, unlike blending: the shader's sample mask
        // (impostor.frag.glsl). Single-sampled, coverage would be a dither of one sample: it cuts at half.
        const std::uint32_t samples = static_cast<std::uint32_t>(target.samples);
        desc.layout = layout_;
        desc.cullMode = VK_CULL_MODE_NONE;  // a quad facing the eye: its winding is not worth deriving
        // One pipeline of each pass per impostor-blend setting (the shaders' BLEND / kBlend): blended
        // cells, or the nearest cell with one fetch.
        for (std::uint32_t blend = 0; blend < 2; ++blend) {
            desc.vertexConstants = {0u, blend};
            desc.fragmentConstants = {samples, blend};
            pipeline_[blend] = gpu::createGraphicsPipeline(context, desc);
            // The shadow map's: depth only, the quad facing the light, biased as the meshes' shadows are.
            gpu::GraphicsPipelineDesc shadow = desc;
            shadow.fragmentShader = impostor_shadow_frag_spv;
            shadow.colorFormats = {};
            shadow.depthFormat = kShadowFormat;
            shadow.samples = VK_SAMPLE_COUNT_1_BIT;
            shadow.fragmentConstants = {0u, blend};
            shadow.depthBiasConstant = 1.0f;
            shadow.depthBiasSlope = 1.5f;
            shadow.vertexConstants = {1u, blend};  // SHADOW_PASS
            shadowPipeline_[blend] = gpu::createGraphicsPipeline(context, shadow);
        }
    } catch (...) {
        release();
        throw;
    }
}

ImpostorDraw::~ImpostorDraw() { release(); }

void ImpostorDraw::release() {
    for (VkPipeline* pipeline : {&shadowPipeline_[0], &shadowPipeline_[1], &pipeline_[0], &pipeline_[1]}) {
        if (*pipeline) vkDestroyPipeline(context_.device, *pipeline, nullptr);
        *pipeline = VK_NULL_HANDLE;
    }
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
    if (drawsPipeline_) vkDestroyPipeline(context_.device, drawsPipeline_, nullptr);
    if (drawsLayout_) vkDestroyPipelineLayout(context_.device, drawsLayout_, nullptr);
    drawsPipeline_ = VK_NULL_HANDLE, drawsLayout_ = VK_NULL_HANDLE;
    set_.reset();
    colourSet_.reset();
    drawsSet_.reset();
    gpu::destroyBuffer(context_, draws_);
    gpu::destroyBuffer(context_, quad_);
}

void ImpostorDraw::recordDraws(VkCommandBuffer cmd) const {
    // The previous frame's indirect reads come first; culling's count is ready (the cull pass ends
    // with a barrier to every later stage).
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, 0},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const VkDescriptorSet set = drawsSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, drawsLayout_, 0, 1, &set, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, drawsPipeline_);
    const DrawsPush push{maxDraws_, characters_};
    vkCmdPushConstants(cmd, drawsLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
}

void ImpostorDraw::recordShadows(VkCommandBuffer cmd, VkDescriptorSet lightSet, const ScenePush& push,
                                 bool blend) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadowPipeline_[blend ? 1 : 0]);
    const VkDescriptorSet sets[3] = {lightSet, set_->set(), atlas_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 3, sets, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, kStages, 0, sizeof push, &push);
    vkCmdBindIndexBuffer(cmd, quad_.buffer, 0, VK_INDEX_TYPE_UINT32);
    constexpr VkDeviceSize stride = sizeof(gpu::DrawIndexedCommand);
    vkCmdDrawIndexedIndirectCount(cmd, draws_.buffer, sizeof(gpu::ImpostorDrawsHeader) + maxDraws_ * stride,
                                  draws_.buffer, offsetof(gpu::ImpostorDrawsHeader, shadowDrawCount), maxDraws_,
                                  static_cast<std::uint32_t>(stride));
}

void ImpostorDraw::record(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const ScenePush& push, bool blend) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_[blend ? 1 : 0]);
    const VkDescriptorSet sets[3] = {sceneSet, (colourSet_ ? colourSet_ : set_)->set(), atlas_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 3, sets, 0, nullptr);
    vkCmdPushConstants(cmd, layout_, kStages, 0, sizeof push, &push);
    // Six vertices per impostor in one draw, no index buffer. The Count form with a count of 1 rather
    // than vkCmdDrawIndirect: lavapipe (Mesa 22.3) kept the count buffer of the mesh draw before it and
    // drew nothing. Same cost on other devices.
    vkCmdBindIndexBuffer(cmd, quad_.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexedIndirectCount(cmd, draws_.buffer, sizeof(gpu::ImpostorDrawsHeader), draws_.buffer,
                                  offsetof(gpu::ImpostorDrawsHeader, drawCount), maxDraws_, sizeof(gpu::DrawIndexedCommand));
}

}  // namespace render
