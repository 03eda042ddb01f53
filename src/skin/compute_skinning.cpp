#include "skin/compute_skinning.h"

#include <algorithm>
#include <array>

#include "gpu/gpu_timer.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_buffers.h"
#include "skin.comp.spv.h"

namespace skin {
namespace {

constexpr std::uint32_t kWorkgroupSize = 64;  // WORKGROUP_SIZE in skin.comp.glsl

// Characters per workgroup: each reuses the thread's bind-pose vertex, but all their bones must
// fit the shared memory (kept under 16 KiB so several workgroups share a multiprocessor).
std::uint32_t charactersPerGroup(const gpu::VulkanContext& context, std::uint32_t joints) {
    const std::uint32_t budget = std::min<std::uint32_t>(16384, context.properties.limits.maxComputeSharedMemorySize);
    const std::uint32_t perCharacter = joints * static_cast<std::uint32_t>(sizeof(gpu::BoneRows));
    if (perCharacter > context.properties.limits.maxComputeSharedMemorySize)
        throw gpu::Error("compute: " + std::to_string(joints) + " joints do not fit in shared memory");
    return std::clamp<std::uint32_t>(budget / perCharacter, 1, 8);
}


}  // namespace

ComputeSkinning::ComputeSkinning(const MethodSetup& setup, bool once)
    : context_(setup.context),
      crowd_(setup.crowd),
      once_(once),
      charactersPerGroup_(charactersPerGroup(setup.context, setup.crowd.jointCount())),
      skinned_(context_, crowd_.characterCount(), crowd_.vertexCount(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      descriptors_(context_, VK_SHADER_STAGE_COMPUTE_BIT, skinningBindings(crowd_, skinned_)),
      draw_(setup, crowd_.vertexCount()) {
    const VkDescriptorSetLayout setLayout = descriptors_.layout();
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::SkinPassParams)};
    pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout, 1}, {&push, 1});
    const std::uint32_t constants[2] = {charactersPerGroup_, crowd_.jointCount()};
    pipeline_ = gpu::createComputePipeline(context_, skin_comp_spv, pipelineLayout_, constants);
}

ComputeSkinning::~ComputeSkinning() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);
    vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
}

void ComputeSkinning::recordDispatches(VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const VkDescriptorSet set = descriptors_.set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set, 0, nullptr);
    const std::uint32_t groupsX = (crowd_.vertexCount() + kWorkgroupSize - 1) / kWorkgroupSize;
    // The y dimension of a dispatch is limited (65,535 groups on many devices): large crowds take several.
    const std::uint32_t maxGroupsY = context_.properties.limits.maxComputeWorkGroupCount[1];
    const std::uint32_t perDispatch = maxGroupsY * charactersPerGroup_;
    for (std::uint32_t first = 0; first < crowd_.characterCount(); first += perDispatch) {
        const std::uint32_t count = std::min(perDispatch, crowd_.characterCount() - first);
        gpu::SkinPassParams params{};
        params.counts = {count, crowd_.vertexCount(), 1, first};
        params.strides = {crowd_.vertexCount(), crowd_.boneStride(), 0, 0};
        vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof params, &params);
        vkCmdDispatch(cmd, groupsX, (count + charactersPerGroup_ - 1) / charactersPerGroup_, 1);
    }
}

void ComputeSkinning::recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) {
    if (once_ && skinnedOnce_) return;  // the ceiling: vertices stay as the first frame left them
    const gpu::Access computeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    skinned_.barrierBeforeWrite(cmd, computeWrite);
    recordDispatches(cmd);
    skinned_.barrierAfterWrite(cmd, computeWrite);
    timer.mark(cmd, "skin");
    skinnedOnce_ = true;
}

void ComputeSkinning::recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) {
    draw_.record(cmd, sceneSet, push, skinned_.vertices());
}

std::vector<MemoryItem> ComputeSkinning::memory() const {
    return {{"skinned vertex buffer", skinned_.bytes()}, {"draw commands", draw_.indirectBytes()}};
}

}  // namespace skin
