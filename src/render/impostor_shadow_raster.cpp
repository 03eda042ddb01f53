#include "render/impostor_shadow_raster.h"

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "gpu_types.h"
#include "impostor_shadow_raster.comp.spv.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/impostor_atlas.h"
#include "render/shadow_map.h"
#include "render/shadow_raster.h"

namespace render {
namespace {

// impostor_shadow_raster.comp.glsl's ImpostorShadowFrame.
struct ImpostorShadowFrame {
    ShadowRasterLight light;
    glm::vec4 lightDirection;
    glm::uvec4 sizes;
};

// Workgroups a cascade: each takes casters in turn, or a share of one when there are fewer casters
// (impostor_shadow_raster.comp.glsl), so the dispatch needs no count from the GPU; enough to fill an
// H100 (132 SMs) many times over.
constexpr std::uint32_t kWorkgroups = 4096;

constexpr gpu::Access kComputeReadWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr gpu::Access kComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
constexpr gpu::Access kUpdateWrite{VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};

}  // namespace

ImpostorShadowRaster::ImpostorShadowRaster(const gpu::VulkanContext& context, const CrowdBuffers& crowd,
                                           const DrawLists& lists, const ImpostorAtlas& atlas, VkBuffer depth,
                                           std::uint32_t mapSize)
    : context_(context), lists_(lists), atlas_(atlas), mapSize_(mapSize) {
    try {
        frame_ = gpu::createBuffer(context, sizeof(ImpostorShadowFrame),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   gpu::MemoryUse::DeviceLocal, "impostor shadow casters' light");
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding bindings[] = {{storage, atlas.modelTable().buffer},
                                               {storage, crowd.characters().buffer},
                                               {storage, lists.impostorList().buffer},
                                               {storage, lists.impostorFrame().buffer},
                                               {storage, depth},
                                               {storage, frame_.buffer}};
        set_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
        const VkDescriptorSetLayout sets[] = {set_->layout(), atlas.setLayout()};
        layout_ = gpu::createPipelineLayout(context, sets, {});
        pipeline_ = gpu::createComputePipeline(context, impostor_shadow_raster_comp_spv, layout_, {});
    } catch (...) {
        release();
        throw;
    }
}

ImpostorShadowRaster::~ImpostorShadowRaster() { release(); }

void ImpostorShadowRaster::release() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    set_.reset();
    gpu::destroyBuffer(context_, frame_);
}

void ImpostorShadowRaster::record(VkCommandBuffer cmd, const ShadowCascades& cascades, bool blend) {
    ImpostorShadowFrame frame{shadowRasterLight(cascades, mapSize_), glm::vec4(lightDirection(), 0.0f),
                              glm::uvec4(mapSize_, lists_.characterCount(), cascades.count, blend ? 1u : 0u)};
    // The previous frame's dispatch read the light before it is written again.
    gpu::bufferBarrier(cmd, frame_.buffer, kComputeRead, kUpdateWrite);
    vkCmdUpdateBuffer(cmd, frame_.buffer, 0, sizeof frame, &frame);
    gpu::bufferBarrier(cmd, frame_.buffer, kUpdateWrite, kComputeRead);
    // The mesh casters' atomic mins came first: both passes write the depth buffer.
    gpu::memoryBarrier(cmd, kComputeReadWrite, kComputeReadWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    const VkDescriptorSet sets[2] = {set_->set(), atlas_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 2, sets, 0, nullptr);
    vkCmdDispatch(cmd, kWorkgroups, 1, cascades.count);
}

}  // namespace render
