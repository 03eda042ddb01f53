#include "skin/fragment_skin_pass.h"

#include <algorithm>

#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "skin_fragment.vert.spv.h"

namespace skin {

FragmentSkinPass::FragmentSkinPass(const MethodSetup& setup, const SkinnedVertexBuffer& skinned,
                                   std::span<const std::uint32_t> fragmentShader, std::vector<VkFormat> colorFormats)
    : context_(setup.context),
      bucketCount_(setup.lists.bucketCount()),
      layout_(planSkinTargets(setup.lists.skinnedCapacity(), maxSkinTargetDimension(setup.context, setup.maxTargetDimension))) {
    try {
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        // two-pass writes attachments and copies them, never these bindings, so its buffer may outgrow the
        // storage range: bind what the range allows. two-pass-direct stores into them, and its buffer is
        // refused past the range (skin/skinned_vertex_buffer.h), so it is bound whole.
        const VkDeviceSize stream = skinned.streamBytes();
        const VkDeviceSize bound = std::min<VkDeviceSize>(stream, context_.properties.limits.maxStorageBufferRange);
        const gpu::BufferBinding bindings[] = {{storage, setup.pool.bindVertices().buffer},
                                               {storage, setup.crowd.bones().buffer},
                                               {storage, skinned.buffer(), 0, bound},
                                               {storage, skinned.buffer(), stream, bound},
                                               {storage, setup.crowd.characters().buffer},
                                               {storage, setup.lists.bucketRecords().buffer},
                                               {storage, setup.lists.bucketFrames().buffer},
                                               {storage, setup.lists.visible().buffer},
                                               {storage, setup.lists.shadowStates().buffer},
                                               {storage, setup.pool.lodMorphTargets().buffer}};
        descriptors_ = std::make_unique<gpu::DescriptorBundle>(
            context_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, bindings);
        const VkDescriptorSetLayout setLayout = descriptors_->layout();
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(gpu::SkinPassParams)};
        pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout, 1}, {&push, 1});
        gpu::GraphicsPipelineDesc desc;
        desc.vertexShader = skin_fragment_vert_spv;
        desc.fragmentShader = fragmentShader;
        desc.colorFormats = std::move(colorFormats);
        desc.layout = pipelineLayout_;
        desc.cullMode = VK_CULL_MODE_NONE;
        // One pipeline for the buckets of each model's last level (nothing to morph into), one for the
        // others (skin_fragment.frag.glsl, kMorphs).
        for (std::uint32_t morphs = 0; morphs < 2; ++morphs) {
            desc.fragmentConstants = {morphs};
            pipelines_[morphs] = gpu::createGraphicsPipeline(context_, desc);
        }
        for (const gpu::BucketRecord& bucket : setup.lists.buckets()) bucketMorphs_.push_back(bucket.list.y + 1 < LOD_COUNT);
    } catch (...) {
        release();
        throw;
    }
}

FragmentSkinPass::~FragmentSkinPass() { release(); }

void FragmentSkinPass::release() {
    for (VkPipeline& pipeline : pipelines_) {
        if (pipeline) vkDestroyPipeline(context_.device, pipeline, nullptr);
        pipeline = VK_NULL_HANDLE;
    }
    if (pipelineLayout_) vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
    pipelineLayout_ = VK_NULL_HANDLE;
    descriptors_.reset();
}

void FragmentSkinPass::recordTile(VkCommandBuffer cmd, std::uint32_t tile) const {
    const VkDescriptorSet set = descriptors_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
    const VkExtent2D extent = layout_.tileExtent(tile);
    gpu::setViewportAndScissor(cmd, extent);
    gpu::SkinPassParams params{};
    params.target = glm::uvec4(layout_.width, layout_.firstRow(tile), extent.height, 0u);
    vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof params,
                       &params);
    // A bucket's rectangle a draw (instance b is bucket b), each with its level's pipeline (the same
    // layout: the set and push constants stay bound).
    VkPipeline bound = VK_NULL_HANDLE;
    for (std::uint32_t b = 0; b < bucketCount_; ++b) {
        const VkPipeline pipeline = pipelines_[bucketMorphs_[b] ? 1 : 0];
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        vkCmdDraw(cmd, 6, 1, 0, b);
    }
}

}  // namespace skin
