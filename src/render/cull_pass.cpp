#include "render/cull_pass.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "crowd/cull_reference.h"
#include "cull.comp.spv.h"
#include "cull_cutoff.comp.spv.h"
#include "cull_emit.comp.spv.h"
#include "cull_finalize.comp.spv.h"
#include "cull_resolve.comp.spv.h"
#include "cull_split.comp.spv.h"
#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

const char* cullModeName(CullMode mode) {
    switch (mode) {
        case CullMode::Gpu: return "gpu";
        case CullMode::Cpu: return "cpu";
        case CullMode::Off: return "off";
    }
    return "?";
}

bool parseCullMode(const std::string& name, CullMode& mode) {
    for (CullMode m : {CullMode::Gpu, CullMode::Cpu, CullMode::Off})
        if (name == cullModeName(m)) return mode = m, true;
    return false;
}

gpu::CullUniforms makeCullUniforms(const CullSettings& settings, const glm::mat4& viewProjection, const glm::vec3& eye,
                                   float verticalFov, std::uint32_t viewportHeight, std::uint32_t characters,
                                   std::uint32_t buckets, std::uint32_t maxGroups) {
    gpu::CullUniforms u{};
    const std::array<glm::vec4, 6> planes = crowd::frustumPlanes(viewProjection);
    std::copy(planes.begin(), planes.end(), u.planes);
    u.camera = glm::vec4(eye, static_cast<float>(viewportHeight) / (2.0f * std::tan(0.5f * verticalFov)));
    u.lod = glm::vec4(settings.lodThresholds[0], settings.lodThresholds[1], settings.hysteresis,
                      settings.lod && settings.impostors ? settings.impostorThreshold : 0.0f);
    u.flags = glm::uvec4(characters, settings.mode != CullMode::Off ? 1u : 0u, settings.lod ? 1u : 0u, buckets);
    u.limits = glm::uvec4(maxGroups, 0u, 0u, 0u);
    u.fade.x = settings.lod && settings.lodFade && settings.hysteresis > 0.0f ? 1u : 0u;
    return u;
}

void setShadowUniforms(gpu::CullUniforms& u, const CullSettings& settings, bool shadows,
                       const ShadowCascades& cascades, std::uint32_t mapSize, const glm::vec3& towardsLight) {
    u.limits.y = shadows ? 1u : 0u;
    u.light = glm::vec4(towardsLight, 0.0f);
    for (std::uint32_t c = 0; c < kMostShadowCascades; ++c) {
        // Unused cascades keep no sphere (a plane everything is behind), so no mask bit is ever set for them.
        std::array<glm::vec4, 6> planes;
        planes.fill(glm::vec4(0.0f, 0.0f, 0.0f, -1e30f));
        if (c < cascades.count) planes = crowd::frustumPlanes(cascades.clip[c]);
        std::copy(planes.begin(), planes.end(), u.cascadePlanes + 6 * c);
        // An orthographic projection: clip x = row 0 . (p, 1), so a world unit spans |row 0's xyz| of clip
        // space's 2, times half the square's texels; the finer of x and y (a caster is never drawn coarser
        // than either axis allows).
        const glm::mat4& m = cascades.clip[c];
        auto rowLength = [&](int i) { return glm::length(glm::vec3(m[0][i], m[1][i], m[2][i])); };
        const float squareTexels = cascades.square[c].z * static_cast<float>(mapSize);
        u.cascadeTexels[static_cast<int>(c)] = c < cascades.count ? 0.5f * squareTexels * std::max(rowLength(0), rowLength(1)) : 0.0f;
    }
    u.shadow = glm::vec4(0.0f, settings.shadowLodThresholds[0], settings.shadowLodThresholds[1], settings.shadowMinTexels);
    u.shadowFlags.x = settings.shadowLod ? 1u : 0u;
    u.shadowFlags.z = cascades.count;
}

namespace {

struct EmitPush {
    std::uint32_t fixedLayout;
    std::uint32_t characterDraws;
    std::uint32_t shadowDrawBase;
    std::uint32_t slotBoneRows;
    std::uint32_t fadingDrawBase;
};

// The per-character draws' binding in the cull passes' set (cull_emit.comp.glsl).
constexpr std::uint32_t kCharacterDrawsBinding = 11;

constexpr VkPipelineStageFlags2 kConsumers =
    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT;
constexpr gpu::Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr gpu::Access kTransferWrite{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
                                     VK_ACCESS_2_TRANSFER_WRITE_BIT};

}  // namespace

CullPass::CullPass(const gpu::VulkanContext& context, const GeometryPool& pool, const CrowdBuffers& crowd,
                   DrawLists& lists, std::uint32_t framesInFlight)
    : context_(context), pool_(pool), crowd_(crowd), lists_(lists) {
    // A storage buffer, not a uniform buffer: lavapipe (Mesa 22.3) compiles a new copy of a large shader
    // whose branches read uniform-buffer values at every bind and never frees it (gpu_types.h).
    const VkDeviceSize align = context.properties.limits.minStorageBufferOffsetAlignment;
    uniformStride_ = (sizeof(gpu::CullUniforms) + align - 1) / align * align;
    uniforms_ = gpu::createBuffer(context, uniformStride_ * framesInFlight, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryUse::HostUpload, "cull uniforms");
    try {
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding bindings[] = {
            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, uniforms_.buffer, 0, sizeof(gpu::CullUniforms)},
            {storage, pool.modelTable().buffer},         {storage, crowd.characters().buffer},
            {storage, lists.bucketRecords().buffer},     {storage, lists.bucketFrames().buffer},
            {storage, lists.visible().buffer},           {storage, lists.lodState().buffer},
            {storage, lists.totals().buffer},            {storage, lists.bucketDraws().buffer},
            {storage, lists.skinDispatches().buffer},    {storage, lists.draws().buffer},
            {storage, lists.characterDraws().buffer},    {storage, lists.impostorFrame().buffer},
            {storage, lists.impostorList().buffer},      {storage, lists.meshCut().buffer},
            {storage, lists.meshCandidates().buffer},    {storage, lists.meshBoundary().buffer},
            {storage, lists.shadowStates().buffer}};
        descriptors_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, bindings);
        const VkDescriptorSetLayout setLayout = descriptors_->layout();
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(EmitPush)};
        layout_ = gpu::createPipelineLayout(context, {&setLayout, 1}, {&push, 1});
        cull_ = createPipeline(cull_comp_spv);
        finalize_ = createPipeline(cull_finalize_comp_spv);
        emit_ = createPipeline(cull_emit_comp_spv);
        cutoff_ = createPipeline(cull_cutoff_comp_spv);
        split_ = createPipeline(cull_split_comp_spv);
        resolve_ = createPipeline(cull_resolve_comp_spv);
    } catch (...) {
        release();
        throw;
    }
}

CullPass::~CullPass() { release(); }

void CullPass::rebindCharacterDraws() {
    descriptors_->rebind(kCharacterDrawsBinding, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lists_.characterDraws().buffer});
}

void CullPass::release() {
    for (VkPipeline* p : {&resolve_, &split_, &cutoff_, &emit_, &finalize_, &cull_}) {
        if (*p) vkDestroyPipeline(context_.device, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
    descriptors_.reset();
    gpu::destroyBuffer(context_, uniforms_);
}

VkPipeline CullPass::createPipeline(std::span<const std::uint32_t> spirv) {
    return gpu::createComputePipeline(context_, spirv, layout_, {});
}

void CullPass::record(VkCommandBuffer cmd, std::uint32_t frameSlot, const gpu::CullUniforms& cullUniforms,
                      CullMode mode, bool fixedLayout, bool characterDraws) {
    if (characterDraws && !lists_.hasCharacterDraws())
        throw gpu::Error("cull: per-character draws asked for, but the draw lists were made without them");
    gpu::CullUniforms uniforms = cullUniforms;
    uniforms.shadowFlags.y = lists_.shadowListBase();  // where the shadow lists start (cull_lists.glsl.inc)
    const VkDeviceSize offset = uniformStride_ * frameSlot;
    std::memcpy(static_cast<std::byte*>(uniforms_.mapped) + offset, &uniforms, sizeof uniforms);
    // The previous frame's skinning, draws and readback must be done with the lists before they are rewritten.
    gpu::memoryBarrier(cmd, {kConsumers, 0}, {kTransferWrite.stage | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0});
    vkCmdFillBuffer(cmd, lists_.bucketFrames().buffer, 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, lists_.impostorFrame().buffer, 0, VK_WHOLE_SIZE, 0);
    if (characterDraws) vkCmdFillBuffer(cmd, lists_.characterDraws().buffer, 0, VK_WHOLE_SIZE, 0);
    const bool meshCut = uniforms.limits.z != 0u && mode != CullMode::Cpu;
    if (meshCut) vkCmdFillBuffer(cmd, lists_.meshCut().buffer, 0, VK_WHOLE_SIZE, 0);  // histograms and tie bits
    if (mode == CullMode::Cpu) recordCpuCulling(cmd, frameSlot, uniforms);
    gpu::memoryBarrier(cmd, kTransferWrite, kComputeWrite);

    const VkDescriptorSet set = descriptors_->set();
    const auto dynamicOffset = static_cast<std::uint32_t>(offset);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 1, &dynamicOffset);
    // Bone blocks per mesh slot: the emit pass gives each listed character its slot's block.
    const EmitPush push{fixedLayout ? 1u : 0u, characterDraws ? 1u : 0u, lists_.drawCapacity(), crowd_.slotBoneRows(),
                        lists_.fadingDrawBase()};
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    if (mode != CullMode::Cpu) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cull_);
        const std::uint32_t groups = (lists_.characterCount() + CULL_WORKGROUP_SIZE - 1) / CULL_WORKGROUP_SIZE;
        vkCmdDispatch(cmd, std::clamp(groups, 1u, uniforms.limits.x), 1, 1);
        gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);
    }
    if (meshCut) recordMeshCut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, finalize_);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, emit_);
    vkCmdDispatchIndirect(cmd, lists_.totals().buffer, offsetof(gpu::DrawTotals, emitDispatch));
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {kConsumers, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                        VK_ACCESS_2_UNIFORM_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT});
    // The counts go to the host for statistics (read once this frame's fence has signalled).
    const VkBufferCopy counts{0, 0, lists_.bucketFrames().size};
    vkCmdCopyBuffer(cmd, lists_.bucketFrames().buffer, lists_.readback(frameSlot).buffer, 1, &counts);
    const VkBufferCopy impostors{0, lists_.bucketFrames().size, sizeof(gpu::ImpostorFrame)};
    vkCmdCopyBuffer(cmd, lists_.impostorFrame().buffer, lists_.readback(frameSlot).buffer, 1, &impostors);
}

void CullPass::recordMeshCut(VkCommandBuffer cmd) {
    // Three dispatches, each reading what the previous wrote: the cut's coarse bucket (one workgroup),
    // every candidate judged against it (indirect: only the GPU knows how many), the cut's bucket
    // resolved to the exact size and index (one workgroup).
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cutoff_);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, split_);
    vkCmdDispatchIndirect(cmd, lists_.meshCut().buffer, offsetof(gpu::MeshCut, splitDispatch));
    gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolve_);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);
}

void CullPass::recordCpuCulling(VkCommandBuffer cmd, std::uint32_t frameSlot, const gpu::CullUniforms& uniforms) {
    cpuLodState_.resize(lists_.characterCount(), 0u);
    std::vector<std::uint32_t> impostorList;
    std::uint32_t demoted = 0;
    crowd::ShadowLists shadows;
    const crowd::VisibleLists visible = crowd::cullOnCpu(uniforms, crowd_.records(), pool_.models(), cpuLodState_,
                                                         &impostorList, &demoted, &shadows);
    // The staging buffer: bucket counts, visible and shadow lists, impostor counts, impostor lists, shadow states.
    const gpu::Buffer& staging = lists_.cpuStaging(frameSlot);
    std::byte* base = static_cast<std::byte*>(staging.mapped);
    const VkDeviceSize framesAt = 0, listsAt = lists_.bucketFrames().size, impostorAt = listsAt + lists_.visible().size,
                       impostorListAt = impostorAt + sizeof(gpu::ImpostorFrame),
                       statesAt = impostorListAt + lists_.impostorList().size;
    auto* frames = reinterpret_cast<gpu::BucketFrame*>(base + framesAt);
    auto* list = reinterpret_cast<std::uint32_t*>(base + listsAt);
    for (std::size_t b = 0; b < visible.size(); ++b) {
        frames[b] = {static_cast<std::uint32_t>(visible[b].size()), 0u, 0u,
                     static_cast<std::uint32_t>(shadows.casters[b].size())};
        std::copy(visible[b].begin(), visible[b].end(), list + lists_.buckets()[b].list.z);
        std::copy(shadows.casters[b].begin(), shadows.casters[b].end(),
                  list + lists_.shadowListBase() + lists_.buckets()[b].list.z);
    }
    gpu::ImpostorFrame impostors{};
    impostors.count = static_cast<std::uint32_t>(impostorList.size());
    impostors.demoted = demoted;
    impostors.shadowCount = static_cast<std::uint32_t>(shadows.impostors.size());
    std::memcpy(base + impostorAt, &impostors, sizeof impostors);
    auto* impostorEntries = reinterpret_cast<std::uint32_t*>(base + impostorListAt);
    std::copy(impostorList.begin(), impostorList.end(), impostorEntries);
    std::copy(shadows.impostors.begin(), shadows.impostors.end(), impostorEntries + lists_.characterCount());
    std::copy(shadows.states.begin(), shadows.states.end(), reinterpret_cast<std::uint32_t*>(base + statesAt));

    // The fill of the counts (just recorded) must land before the copy overwrites them.
    gpu::memoryBarrier(cmd, kTransferWrite, kTransferWrite);
    const VkBufferCopy regions[] = {{framesAt, 0, lists_.bucketFrames().size},
                                    {listsAt, 0, lists_.visible().size},
                                    {impostorAt, 0, sizeof impostors},
                                    {impostorListAt, 0, lists_.impostorList().size},
                                    {statesAt, 0, lists_.shadowStates().size}};
    const VkBuffer targets[] = {lists_.bucketFrames().buffer, lists_.visible().buffer, lists_.impostorFrame().buffer,
                                lists_.impostorList().buffer, lists_.shadowStates().buffer};
    for (int i = 0; i < 5; ++i) vkCmdCopyBuffer(cmd, staging.buffer, targets[i], 1, &regions[i]);
}

}  // namespace render
