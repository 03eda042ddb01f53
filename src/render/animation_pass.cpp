#include "render/animation_pass.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <span>

#include "crowd/epoch.h"
#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "motion.comp.spv.h"
#include "motion_scatter.comp.spv.h"
#include "palette.comp.spv.h"
#include "palette_dispatch.comp.spv.h"

namespace render {
namespace {

// The palette pass's threads per workgroup (palette.comp.glsl): a group takes this many joints.
constexpr std::uint32_t kPaletteThreads = 64;
// The bones' binding in the palette set (palette.comp.glsl).
constexpr std::uint32_t kPaletteBonesBinding = 10;

constexpr gpu::Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};

// A table as a device buffer; empty tables get one zeroed element, since buffers cannot be empty.
template <typename T>
gpu::Buffer upload(const gpu::VulkanContext& context, const std::vector<T>& table, const char* what) {
    std::vector<T> padded = table;
    if (padded.empty()) padded.emplace_back();
    return gpu::createBufferWithData(context, std::as_bytes(std::span(padded)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, what);
}

std::uint32_t groupsFor(std::uint32_t items, std::uint32_t perGroup, std::uint32_t maxGroups) {
    return std::clamp((items + perGroup - 1) / perGroup, 1u, maxGroups);
}

}  // namespace

const char* animationPathName(AnimationPath path) { return path == AnimationPath::Cpu ? "cpu" : "gpu"; }

bool parseAnimationPath(const std::string& name, AnimationPath& path) {
    for (AnimationPath p : {AnimationPath::Cpu, AnimationPath::Gpu})
        if (name == animationPathName(p)) return path = p, true;
    return false;
}

AnimationPass::AnimationPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, CrowdBuffers& buffers,
                             const DrawLists& lists, const TerrainBuffer& terrain, std::uint32_t framesInFlight)
    : context_(context), buffers_(buffers), lists_(lists) {
    try {
        const anim::ClipLibrary& library = crowd.library();
        for (std::uint32_t m = 0; m < crowd.models().size(); ++m) modelJoints_.push_back(library.jointCount(m));
        library_.push_back(upload(context, library.models(), "animation models"));
        library_.push_back(upload(context, library.joints(), "animation joints"));
        library_.push_back(upload(context, library.clips(), "animation clips"));
        library_.push_back(upload(context, library.tracks(), "animation tracks"));
        library_.push_back(upload(context, library.keyTimes(), "animation key times"));
        library_.push_back(upload(context, library.keyValues(), "animation key values"));
        library_.push_back(upload(context, library.rootSamples(), "root motion"));
        for (const gpu::Buffer& b : library_) libraryBytes_ += b.size;
        const VkDeviceSize characters = std::max<VkDeviceSize>(1, crowd.size());
        const VkDeviceSize segmentBytes = characters * sizeof(gpu::MotionRecord);
        motions_ = gpu::createBuffer(context, segmentBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     gpu::MemoryUse::DeviceLocal, "motion segments");
        // Each array starts at the storage offset alignment (a multiple of 16: the tints' vec4s stay aligned).
        const VkDeviceSize align = std::max<VkDeviceSize>(16, context.properties.limits.minStorageBufferOffsetAlignment);
        auto aligned = [align](VkDeviceSize bytes) { return (bytes + align - 1) / align * align; };
        indicesOffset_ = aligned(segmentBytes);
        tintsOffset_ = aligned(indicesOffset_ + characters * sizeof(std::uint32_t));
        wordsOffset_ = aligned(tintsOffset_ + characters * sizeof(glm::vec4));
        countsOffset_ = aligned(wordsOffset_ + characters * sizeof(glm::uvec2));
        const VkDeviceSize stagingBytes = countsOffset_ + characters * sizeof(std::uint32_t);
        driven_ = std::make_unique<DrivenPass>(context, crowd, buffers, motions_, framesInFlight);
        constexpr VkDescriptorType storageType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            staging_.push_back(gpu::createBuffer(context, stagingBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                 gpu::MemoryUse::HostUpload, "motion segments (upload)"));
            const VkBuffer staged = staging_.back().buffer;
            const gpu::BufferBinding scatter[] = {{storageType, staged, 0, segmentBytes},
                                                  {storageType, staged, indicesOffset_, tintsOffset_ - indicesOffset_},
                                                  {storageType, motions_.buffer},
                                                  {storageType, staged, tintsOffset_, wordsOffset_ - tintsOffset_},
                                                  {storageType, staged, wordsOffset_, countsOffset_ - wordsOffset_},
                                                  {storageType, buffers.characters().buffer},
                                                  {storageType, staged, countsOffset_, VK_WHOLE_SIZE},
                                                  {storageType, driven_->heads().buffer}};
            scatterSets_.push_back(std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, scatter));
        }
        dispatches_ = gpu::createBuffer(context, std::max(1u, lists.bucketCount()) * sizeof(glm::uvec4),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                                        gpu::MemoryUse::DeviceLocal, "palette dispatches");

        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        const gpu::BufferBinding motionBindings[] = {{storage, library_[0].buffer},        {storage, library_[2].buffer},
                                                     {storage, library_[6].buffer},        {storage, motions_.buffer},
                                                     {storage, buffers.characters().buffer}, {storage, driven_->models().buffer},
                                                     {storage, driven_->keys().buffer},    {storage, driven_->heads().buffer},
                                                     {storage, driven_->owners().buffer},  {storage, terrain.buffer().buffer}};
        motionSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, motionBindings);
        const gpu::BufferBinding paletteBindings[] = {
            {storage, library_[0].buffer},          {storage, library_[1].buffer},     {storage, library_[2].buffer},
            {storage, library_[3].buffer},          {storage, library_[4].buffer},     {storage, library_[5].buffer},
            {storage, buffers.characters().buffer}, {storage, lists.bucketRecords().buffer},
            {storage, lists.bucketFrames().buffer}, {storage, lists.visible().buffer}, {storage, buffers.bones().buffer},
            {storage, dispatches_.buffer}};
        paletteSet_ = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, paletteBindings);

        const VkDescriptorSetLayout motionSetLayout = motionSet_->layout();
        const VkPushConstantRange motionPush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::MotionPush)};
        motionLayout_ = gpu::createPipelineLayout(context, {&motionSetLayout, 1}, {&motionPush, 1});
        motion_ = gpu::createComputePipeline(context, motion_comp_spv, motionLayout_, {});
        const VkDescriptorSetLayout scatterSetLayout = scatterSets_.front()->layout();
        scatterLayout_ = gpu::createPipelineLayout(context, {&scatterSetLayout, 1}, {&motionPush, 1});
        scatter_ = gpu::createComputePipeline(context, motion_scatter_comp_spv, scatterLayout_, {});
        const VkDescriptorSetLayout paletteSetLayout = paletteSet_->layout();
        const VkPushConstantRange palettePush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::PalettePush)};
        paletteLayout_ = gpu::createPipelineLayout(context, {&paletteSetLayout, 1}, {&palettePush, 1});
        const std::uint32_t small[] = {kPaletteThreads}, large[] = {MAX_ANIMATION_JOINTS};
        palette_ = gpu::createComputePipeline(context, palette_comp_spv, paletteLayout_, small);
        paletteLarge_ = gpu::createComputePipeline(context, palette_comp_spv, paletteLayout_, large);
        paletteDispatch_ = gpu::createComputePipeline(context, palette_dispatch_comp_spv, paletteLayout_, {});
    } catch (...) {
        release();
        throw;
    }
}

AnimationPass::~AnimationPass() { release(); }

void AnimationPass::rebindBones(const CrowdBuffers& buffers) {
    paletteSet_->rebind(kPaletteBonesBinding, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers.bones().buffer});
}

void AnimationPass::release() {
    for (VkPipeline* p : {&scatter_, &paletteDispatch_, &paletteLarge_, &palette_, &motion_}) {
        if (*p) vkDestroyPipeline(context_.device, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
    for (VkPipelineLayout* l : {&scatterLayout_, &paletteLayout_, &motionLayout_}) {
        if (*l) vkDestroyPipelineLayout(context_.device, *l, nullptr);
        *l = VK_NULL_HANDLE;
    }
    paletteSet_.reset();
    motionSet_.reset();
    scatterSets_.clear();
    driven_.reset();
    for (gpu::Buffer& b : staging_) gpu::destroyBuffer(context_, b);
    staging_.clear();
    gpu::destroyBuffer(context_, dispatches_);
    gpu::destroyBuffer(context_, motions_);
    for (gpu::Buffer& b : library_) gpu::destroyBuffer(context_, b);
    library_.clear();
}

void AnimationPass::recordSegmentUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd,
                                        std::uint64_t since) {
    const std::vector<gpu::MotionRecord>& segments = crowd.segments();
    std::byte* base = static_cast<std::byte*>(staging_[frameSlot].mapped);
    auto* staged = reinterpret_cast<gpu::MotionRecord*>(base);
    auto* indices = reinterpret_cast<std::uint32_t*>(base + indicesOffset_);
    auto* tints = reinterpret_cast<glm::vec4*>(base + tintsOffset_);
    auto* words = reinterpret_cast<glm::uvec2*>(base + wordsOffset_);
    auto* keyCounts = reinterpret_cast<std::uint32_t*>(base + countsOffset_);
    std::span<gpu::CharacterRecord> records = buffers_.mutableRecords();
    const crowd::DrivenKeys& keys = crowd.drivenKeys();
    std::uint32_t count = 0;
    auto stage = [&](std::uint32_t c) {
        const crowd::Identity identity = crowd.identity(c);
        const crowd::Driven driven = crowd.drivenBy(c);
        staged[count] = segments[c];
        indices[count] = c;
        tints[count] = identity.tintScale;
        words[count] = glm::uvec2(identity.props, identity.generation);
        // Its key count: the CPU's for a host-driven character; the GPU's own for a device-driven one (and
        // none at all in a crowd without driven keys): 0xFFFFFFFF leaves it.
        keyCounts[count++] = driven == crowd::Driven::DeviceSamples || driven_->keysPerSlot() == 0 ? 0xFFFFFFFFu
                             : driven == crowd::Driven::HostSamples && !keys.empty()                 ? keys.count(c)
                                                                                                      : 0u;
        records[c].tint = identity.tintScale;  // the CPU's copy (the CPU paths upload or cull from it)
        records[c].pose.z = static_cast<float>(identity.props);  // below 2^MAX_PROPS: exact
        records[c].pose.w = std::bit_cast<float>(identity.generation);
    };
    if (!crowd.changes().forEachSince(since, stage))
        for (std::uint32_t c = 0; c < crowd.size(); ++c) stage(c);
    if (count > 0) scatterSegments(cmd, frameSlot, count);
    // The keys after the counts (a changed slot's count is set, then its new keys raise it).
    recordKeyUpload(cmd, frameSlot, crowd, since);
}

void AnimationPass::scatterSegments(VkCommandBuffer cmd, std::uint32_t frameSlot, std::uint32_t count) {
    // The previous frame's passes must be done reading the segments and records the scatter overwrites.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                       kComputeWrite);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    const gpu::MotionPush push{glm::uvec4(count, 0u, 0u, 0u), glm::vec4(0.0f)};
    const VkDescriptorSet set = scatterSets_[frameSlot]->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatterLayout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, scatterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatter_);
    vkCmdDispatch(cmd, groupsFor(count, CULL_WORKGROUP_SIZE, maxGroups), 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
}

void AnimationPass::recordKeyUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd,
                                    std::uint64_t since) {
    driven_->recordUpload(cmd, frameSlot, crowd, since);
}

void AnimationPass::recordMotion(VkCommandBuffer cmd, const crowd::Crowd& crowd, double time) {    // The previous frames' passes must be done reading the records before they are rewritten.
    gpu::memoryBarrier(cmd, {kCharacterReaders, 0}, kComputeWrite);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    // The segments are relative to the crowd's epoch (crowd/epoch.h): so is the time, a small float.
    const auto sinceEpoch = static_cast<float>(time - crowd.epoch());
    const gpu::MotionPush push{glm::uvec4(crowd.size(), maxGroups, driven_->keysPerSlot(), 0u),
                               glm::vec4(sinceEpoch, crowd.drivenClock(time), static_cast<float>(crowd.drivenTiming().extrapolate),
                                         static_cast<float>(crowd.epoch() / crowd::kEpochSeconds))};
    const VkDescriptorSet set = motionSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, motionLayout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, motionLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, motion_);
    vkCmdDispatch(cmd, groupsFor(crowd.size(), CULL_WORKGROUP_SIZE, maxGroups), 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite, {kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
}

void AnimationPass::recordPalettes(VkCommandBuffer cmd) {
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    const VkDescriptorSet set = paletteSet_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, paletteLayout_, 0, 1, &set, 0, nullptr);
    // The previous frame's indirect reads of the dispatches, and its readers of the bones, come first.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | kCharacterReaders, 0}, kComputeWrite);
    const gpu::PalettePush sizes{glm::uvec4(lists_.bucketCount(), maxGroups, 0u, 0u)};
    vkCmdPushConstants(cmd, paletteLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof sizes, &sizes);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, paletteDispatch_);
    vkCmdDispatch(cmd, 1, 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite, {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
    for (std::uint32_t b = 0; b < lists_.bucketCount(); ++b) {
        const std::uint32_t joints = modelJoints_[lists_.buckets()[b].list.x];
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, joints <= kPaletteThreads ? palette_ : paletteLarge_);
        const gpu::PalettePush push{glm::uvec4(b, joints, std::max(1u, kPaletteThreads / joints), 0u)};
        vkCmdPushConstants(cmd, paletteLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatchIndirect(cmd, dispatches_.buffer, b * sizeof(glm::uvec4));
    }
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {kCharacterReaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});
}

}  // namespace render
