#include "render/impostor_raster.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>
#include <span>

#include "gpu/barriers.h"
#include "gpu/error.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/raster_mode.h"
#include "impostor_raster.comp.spv.h"
#include "impostor_resolve.frag.spv.h"

namespace render {

namespace {
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
// Filled each frame, read back by the tests.
constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
// Workgroups of the raster pass at most: its threads stride over the impostor list, so a crowd of
// millions needs no dispatch larger than a device holds at once (an H100 keeps about 270,000 threads).
constexpr std::uint32_t kMaxWorkgroups = 4096;

struct ResolvePush {
    glm::vec4 cameraPosition;
    glm::vec4 viewport;  // offset, extent
};
// The tiles' vertex shader (visibility_tiles.vert.glsl) reads the viewport there.
static_assert(offsetof(ResolvePush, viewport) == 16);
}  // namespace

ImpostorRaster::ImpostorRaster(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                               const DrawLists& lists, const ImpostorAtlas& atlas, VkDescriptorSetLayout sceneSetLayout,
                               const TargetFormat& target, std::uint32_t framesInFlight, float limitPixels,
                               std::uint32_t resolveTilePixels, FarCrowdSizes far)
    : context_(context), crowd_(crowd), lists_(lists), atlas_(atlas), sceneSetLayout_(sceneSetLayout), target_(target),
      resolveTilePixels_(resolveTilePixels), limitPixels_(limitPixels), far_(far), slots_(framesInFlight) {
    requireComputeRaster(context);
    try {
        split_ = gpu::createBuffer(context, sizeof(gpu::ImpostorSplit), kUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                   gpu::MemoryUse::DeviceLocal, "impostor raster split");
        hardwareList_ = gpu::createBuffer(context, std::uint64_t{std::max(lists.characterCount(), 1u)} * 4,
                                          kUsage, gpu::MemoryUse::DeviceLocal,
                                          "impostors left to the hardware rasterizer");
        largeList_ = gpu::createBuffer(context, std::uint64_t{std::max(lists.characterCount(), 1u)} * 4, kUsage,
                                       gpu::MemoryUse::DeviceLocal, "large impostors for the compute rasterizer");
        // The slots' set layouts, with any buffer behind them (never bound).
        const gpu::BufferBinding any{kStorage, split_.buffer};
        const gpu::BufferBinding rasterShape[11] = {any, any, any, any, any, any, any, any, any, any, any};
        rasterPrototype_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, rasterShape);
        resolvePrototype_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_FRAGMENT_BIT,
                                                                    std::span(&any, 1));
        for (std::uint32_t slot = 0; slot < framesInFlight; ++slot) makeVisibility(slot, {1, 1});

        const VkDescriptorSetLayout rasterSets[2] = {rasterPrototype_->layout(), atlas.setLayout()};
        const VkPushConstantRange rasterPush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::ImpostorRasterPush)};
        rasterLayout_ = gpu::createPipelineLayout(context, rasterSets, {&rasterPush, 1});
        // The shader's three passes (impostor_raster.comp.glsl, RASTER_PASS), each its own pipeline.
        const std::uint32_t passes[3] = {0u, 1u, 2u};
        rasterPipeline_ = gpu::createComputePipeline(context, impostor_raster_comp_spv, rasterLayout_, {&passes[0], 1});
        largePipeline_ = gpu::createComputePipeline(context, impostor_raster_comp_spv, rasterLayout_, {&passes[1], 1});
        splatPipeline_ = gpu::createComputePipeline(context, impostor_raster_comp_spv, rasterLayout_, {&passes[2], 1});

        const gpu::BufferBinding drawBindings[] = {{kStorage, pool.modelTable().buffer},
                                                   {kStorage, atlas.modelTable().buffer},
                                                   {kStorage, crowd.characters().buffer},
                                                   {kStorage, lists.impostorList().buffer},
                                                   {kStorage, lists.shadowStates().buffer}};
        drawSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_FRAGMENT_BIT, drawBindings);
        const VkDescriptorSetLayout resolveSets[4] = {sceneSetLayout, drawSet_->layout(), atlas.setLayout(),
                                                      resolvePrototype_->layout()};
        const VkPushConstantRange resolvePush{kResolvePushStages, 0, sizeof(ResolvePush)};
        resolveLayout_ = gpu::createPipelineLayout(context, resolveSets, {&resolvePush, 1});
        resolve_ = std::make_unique<VisibilityResolve>(context, impostor_resolve_frag_spv, resolveLayout_, target,
                                                       framesInFlight, resolveTilePixels);
    } catch (...) {
        release();
        throw;
    }
}

ImpostorRaster::~ImpostorRaster() { release(); }

void ImpostorRaster::release() {
    farLayer_.reset();
    resolve_.reset();
    if (resolveLayout_) vkDestroyPipelineLayout(context_.device, resolveLayout_, nullptr);
    if (rasterPipeline_) vkDestroyPipeline(context_.device, rasterPipeline_, nullptr);
    for (VkPipeline* pipeline : {&largePipeline_, &splatPipeline_}) {
        if (*pipeline) vkDestroyPipeline(context_.device, *pipeline, nullptr);
        *pipeline = VK_NULL_HANDLE;
    }
    if (rasterLayout_) vkDestroyPipelineLayout(context_.device, rasterLayout_, nullptr);
    resolveLayout_ = VK_NULL_HANDLE;
    rasterPipeline_ = VK_NULL_HANDLE, rasterLayout_ = VK_NULL_HANDLE;
    for (Slot& slot : slots_) {
        slot.rasterSet.reset();
        slot.resolveSet.reset();
        gpu::destroyBuffer(context_, slot.visibility);
    }
    rasterPrototype_.reset();
    resolvePrototype_.reset();
    drawSet_.reset();
    gpu::destroyBuffer(context_, hardwareList_);
    gpu::destroyBuffer(context_, largeList_);
    gpu::destroyBuffer(context_, split_);
}

void ImpostorRaster::makeVisibility(std::uint32_t index, VkExtent2D extent) {
    Slot& slot = slots_[index];
    slot.rasterSet.reset();
    slot.resolveSet.reset();
    gpu::destroyBuffer(context_, slot.visibility);
    slot.extent = extent;
    slot.visibility = gpu::createBuffer(context_, visibilityBytes(extent), kUsage,
                                        gpu::MemoryUse::DeviceLocal, "visibility buffer");
    makeSets(index);
}

void ImpostorRaster::makeSets(std::uint32_t index) {
    Slot& slot = slots_[index];
    slot.rasterSet.reset();
    slot.resolveSet.reset();
    // The far layer's buffers, or the visibility buffer in their place (never written: far-crowd off, or
    // a layer too large for one storage binding at this extent).
    slot.farBound = farLayer_ && FarCrowdLayer::fits(context_.properties.limits, slot.extent);
    if (slot.farBound) farLayer_->fit(index, slot.extent);
    const VkBuffer farDepth = slot.farBound ? farLayer_->depth(index).buffer : slot.visibility.buffer;
    const VkBuffer farSums = slot.farBound ? farLayer_->sums(index).buffer : slot.visibility.buffer;
    const gpu::BufferBinding raster[] = {{kStorage, atlas_.modelTable().buffer},
                                         {kStorage, crowd_.characters().buffer},
                                         {kStorage, lists_.impostorList().buffer},
                                         {kStorage, lists_.impostorFrame().buffer},
                                         {kStorage, slot.visibility.buffer},
                                         {kStorage, split_.buffer},
                                         {kStorage, hardwareList_.buffer},
                                         {kStorage, largeList_.buffer},
                                         {kStorage, lists_.shadowStates().buffer},  // the fade shares
                                         {kStorage, farDepth},
                                         {kStorage, farSums}};
    slot.rasterSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, raster);
    const gpu::BufferBinding resolve[] = {{kStorage, slot.visibility.buffer}};
    slot.resolveSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_FRAGMENT_BIT, resolve);
}

void ImpostorRaster::record(VkCommandBuffer cmd, std::uint32_t index, const glm::mat4& viewProjection,
                            const glm::vec3& eye, VkExtent2D extent, bool blend, bool averageFar) {
    Slot& slot = slots_[index];
    // A viewport whose visibility buffer would pass one storage binding on this device: every impostor
    // goes to the hardware path this frame, through the same passes over a one-pixel buffer that stays
    // empty (raster compute refuses such a viewport before: CrowdRecorder::recordCompute). The far layer,
    // four times larger a pixel, is left out on its own where it alone does not fit.
    const VkPhysicalDeviceLimits& limits = context_.properties.limits;
    const bool hardwareOnly = !visibilityFits(limits, extent);
    averageFar = averageFar && !hardwareOnly && FarCrowdLayer::fits(limits, extent);
    const VkExtent2D visibilityExtent = hardwareOnly ? VkExtent2D{1, 1} : extent;
    const bool remake = visibilityExtent.width != slot.extent.width || visibilityExtent.height != slot.extent.height;
    if (averageFar && !farLayer_)
        farLayer_ = std::make_unique<FarCrowdLayer>(context_, sceneSetLayout_, target_,
                                                    static_cast<std::uint32_t>(slots_.size()), resolveTilePixels_);
    if (remake)
        makeVisibility(index, visibilityExtent);
    else if (averageFar && !slot.farBound)
        makeSets(index);  // the layer is new: bind it
    slot.averaged = averageFar;
    // The previous frame's reads of the split, the hardware list and the visibility buffer come first.
    gpu::memoryBarrier(cmd,
                       {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT},
                       {VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    vkCmdFillBuffer(cmd, slot.visibility.buffer, 0, VK_WHOLE_SIZE, VISIBILITY_EMPTY_HIGH);
    if (averageFar) farLayer_->recordClear(cmd, index);
    // The split's counts to 0 and the second dispatch's y and z to 1 (ranges apart: one write each).
    constexpr VkDeviceSize dispatchY = offsetof(gpu::ImpostorSplit, largeDispatch) + 4;
    vkCmdFillBuffer(cmd, split_.buffer, 0, dispatchY, 0u);
    vkCmdFillBuffer(cmd, split_.buffer, dispatchY, 8, 1u);
    vkCmdFillBuffer(cmd, split_.buffer, dispatchY + 8, sizeof(gpu::ImpostorSplit) - dispatchY - 8, 0u);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const VkDescriptorSet sets[2] = {slot.rasterSet->set(), atlas_.set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterLayout_, 0, 2, sets, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rasterPipeline_);
    const std::uint32_t capacity = lists_.characterCount();
    const std::uint32_t groups = std::clamp((capacity + IMPOSTOR_RASTER_WORKGROUP - 1) / IMPOSTOR_RASTER_WORKGROUP, 1u,
                                            std::min(kMaxWorkgroups, context_.properties.limits.maxComputeWorkGroupCount[0]));
    gpu::ImpostorRasterPush push{};
    push.viewProjection = viewProjection;
    push.cameraPosition = glm::vec4(eye, 1.0f);
    push.viewport = glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height),
                              hardwareOnly ? -1.0f : limitPixels_,  // no side is under -1: all to the hardware
                              static_cast<float>(IMPOSTOR_RASTER_LARGE_PIXELS));
    push.limits = glm::uvec4(capacity, groups * IMPOSTOR_RASTER_WORKGROUP,
                             std::min(capacity, context_.properties.limits.maxComputeWorkGroupCount[0]), blend ? 1u : 0u);
    push.far = glm::vec4(averageFar ? far_.averaged : 0.0f, far_.splatted,
                         static_cast<float>(atlas_.plan().mipLevels - 2), 0.0f);  // z: two texels a cell
    vkCmdPushConstants(cmd, rasterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, groups, 1, 1);
    // The large impostors: a workgroup each, as many as the first dispatch listed.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, largePipeline_);
    vkCmdDispatchIndirect(cmd, split_.buffer, offsetof(gpu::ImpostorSplit, largeDispatch));
    // The far layer's splats: the whole list again, each thread splatting the impostors the first pass
    // left for it. Apart from that pass, not among its sub-samples: on the H100 a warp doing both ran
    // slower than either (10,000,000 from above: 9.4 ms a frame where the sub-samples alone took 8.3 ms
    // and the splats, run alone, 3.8; docs/picture-quality.md).
    if (averageFar && far_.splatted > 0.0f) {
        gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                           {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, splatPipeline_);
        vkCmdDispatch(cmd, groups, 1, 1);
    }
    // The impostor draws' pass reads the split's count, the colour draw the hardware list, the tile scan
    // and the resolve the visibility buffer.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
    resolve_->recordTiles(cmd, index, slot.visibility, slot.extent);
    if (averageFar) farLayer_->recordTiles(cmd, index);
}

void ImpostorRaster::recordResolve(VkCommandBuffer cmd, std::uint32_t index, VkDescriptorSet sceneSet,
                                   const glm::vec3& eye, const VkRect2D& viewport, bool blend) const {
    const Slot& slot = slots_[index];
    resolve_->bind(cmd);
    const VkDescriptorSet sets[4] = {sceneSet, drawSet_->set(), atlas_.set(), slot.resolveSet->set()};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, resolveLayout_, 0, 4, sets, 0, nullptr);
    const ResolvePush push{glm::vec4(eye, blend ? 1.0f : 0.0f),
                           glm::vec4(static_cast<float>(viewport.offset.x), static_cast<float>(viewport.offset.y),
                                     static_cast<float>(slot.extent.width), static_cast<float>(slot.extent.height))};
    vkCmdPushConstants(cmd, resolveLayout_, kResolvePushStages, 0, sizeof push, &push);
    resolve_->draw(cmd, index);
}

void ImpostorRaster::recordFarResolve(VkCommandBuffer cmd, std::uint32_t index, VkDescriptorSet sceneSet,
                                      const glm::vec3& eye, const VkRect2D& viewport) const {
    if (slots_[index].averaged) farLayer_->recordResolve(cmd, index, sceneSet, eye, viewport);
}

std::uint64_t ImpostorRaster::bytes() const {
    std::uint64_t total = split_.size + hardwareList_.size + largeList_.size + (farLayer_ ? farLayer_->bytes() : 0);
    for (const Slot& slot : slots_) total += slot.visibility.size;
    return total + resolve_->bytes();
}

}  // namespace render
