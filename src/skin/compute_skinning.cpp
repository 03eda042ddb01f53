#include "skin/compute_skinning.h"

#include <algorithm>

#include "gpu/pass_observer.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "skin.comp.spv.h"

namespace skin {
namespace {

// Every character of each bucket's model in rank order, at the bucket's place in the list: the
// static method skins them all once.
std::vector<std::uint32_t> everyCharacterList(const render::CrowdBuffers& crowd, const render::DrawLists& lists) {
    std::vector<std::uint32_t> list(static_cast<std::size_t>(crowd.characterCount()) * LOD_COUNT + 1, 0u);
    for (std::uint32_t c = 0; c < crowd.characterCount(); ++c) {
        const gpu::CharacterRecord& record = crowd.records()[c];
        for (std::uint32_t l = 0; l < LOD_COUNT; ++l)
            list[lists.buckets()[record.ids.x * LOD_COUNT + l].list.z + record.ids.z] = c;
    }
    return list;
}

}  // namespace

ComputeSkinning::ComputeSkinning(const MethodSetup& setup, Every every)
    : context_(setup.context), lists_(setup.lists), every_(every) {
    try {
        skinned_ = std::make_unique<SkinnedVertexBuffer>(
            context_, once() ? lists_.fixedCapacity() : lists_.skinnedCapacity(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        VkBuffer list = lists_.visible().buffer;
        if (once()) {
            const std::vector<std::uint32_t> all = everyCharacterList(setup.crowd, lists_);
            everyCharacter_ = gpu::createBufferWithData(context_, std::as_bytes(std::span(all)),
                                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "every character (static)");
            list = everyCharacter_.buffer;
        }
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const VkDeviceSize half = skinned_->streamBytes();
        const gpu::BufferBinding bindings[] = {{storage, setup.pool.bindVertices().buffer},
                                               {storage, setup.crowd.bones().buffer},
                                               {storage, skinned_->buffer(), 0, half},
                                               {storage, skinned_->buffer(), half, half},
                                               {storage, setup.crowd.characters().buffer},
                                               {storage, lists_.bucketRecords().buffer},
                                               {storage, lists_.bucketFrames().buffer},
                                               {storage, list},
                                               {storage, lists_.shadowStates().buffer},
                                               {storage, setup.pool.lodMorphTargets().buffer}};
        descriptors_ = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
        const VkDescriptorSetLayout setLayout = descriptors_->layout();
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::SkinPassParams)};
        pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout, 1}, {&push, 1});
        // Per model, a pipeline for its last level (no coarser mesh level to morph into) and one for
        // the others (shaders/skin.comp.glsl, MORPHS).
        for (const gpu::ModelRecord& model : setup.pool.models())
            for (std::uint32_t morphs = 0; morphs < 2; ++morphs) {
                const std::uint32_t constants[3] = {render::skinningCharactersPerGroup(context_, model.info.y), model.info.y,
                                                    morphs};
                pipelines_.push_back(gpu::createComputePipeline(context_, skin_comp_spv, pipelineLayout_, constants));
            }
    } catch (...) {
        release();
        throw;
    }
}

ComputeSkinning::~ComputeSkinning() { release(); }

void ComputeSkinning::release() {
    for (VkPipeline pipeline : pipelines_) vkDestroyPipeline(context_.device, pipeline, nullptr);
    pipelines_.clear();
    if (pipelineLayout_) vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
    pipelineLayout_ = VK_NULL_HANDLE;
    descriptors_.reset();
    gpu::destroyBuffer(context_, everyCharacter_);
    skinned_.reset();
}

void ComputeSkinning::recordDispatches(VkCommandBuffer cmd) {
    const VkDescriptorSet set = descriptors_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set, 0, nullptr);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    for (std::uint32_t b = 0; b < lists_.bucketCount(); ++b) {
        const gpu::BucketRecord& bucket = lists_.buckets()[b];
        const bool morphs = !once() && bucket.list.y + 1 < LOD_COUNT;  // the static ceiling never fades
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[2 * bucket.list.x + (morphs ? 1 : 0)]);
        gpu::SkinPassParams params{};
        params.bucket = glm::uvec4(b, once() ? 1u : 0u, 0u, 0u);
        vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params, &params);
        if (once()) {
            // Every character of the model: the CPU knows the counts.
            if (bucket.list.w == 0) continue;
            const std::uint32_t groups = (bucket.list.w + bucket.fixedLayout.y - 1) / bucket.fixedLayout.y;
            vkCmdDispatch(cmd, std::min(groups, maxGroups), (bucket.mesh.z + CULL_WORKGROUP_SIZE - 1) / CULL_WORKGROUP_SIZE, 1);
        } else {
            vkCmdDispatchIndirect(cmd, lists_.skinDispatches().buffer, b * sizeof(glm::uvec4));
        }
    }
}

void ComputeSkinning::recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) {
    if (once() && skinnedOnce_) return;  // the ceiling: vertices stay as the first frame left them
    const gpu::Access computeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    skinned_->barrierBeforeWrite(cmd, computeWrite);
    recordDispatches(cmd);
    skinned_->barrierAfterWrite(cmd, computeWrite);
    gpu::passDone(passes, cmd, "skin");
    skinnedOnce_ = true;
}

std::vector<MemoryItem> ComputeSkinning::memory() const {
    std::vector<MemoryItem> items = {{"skinned vertex buffer", skinned_->bytes()}};
    if (once()) items.push_back({"every-character list", everyCharacter_.size});
    return items;
}

}  // namespace skin
