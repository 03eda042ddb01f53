#include "render/event_pass.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "anim/soa_palette_job.h"
#include "anim/soa_sampling_job.h"
#include "crowd/epoch.h"
#include "crowd/event_pairs.h"
#include "crowd/segment.h"
#include "event_starts_scatter.comp.spv.h"
#include "events.comp.spv.h"
#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/animation_pass.h"
#include "render/crowd_buffers.h"
#include "render/terrain_buffer.h"
#include "render/draw_lists.h"

namespace render {
namespace {

constexpr gpu::Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};

std::uint32_t groupsFor(std::uint32_t items, std::uint32_t maxGroups) {
    return std::clamp((items + CULL_WORKGROUP_SIZE - 1) / CULL_WORKGROUP_SIZE, 1u, maxGroups);
}

// Joint `joint`'s model-space position in clip `clip`'s own pose at `time`: the CPU animation jobs
// (the GPU palettes' reference) with no placement.
glm::vec3 jointInClip(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float time,
                      std::uint32_t joint) {
    const std::uint32_t joints = library.jointCount(model);
    std::vector<anim::SoaTransform> pose(anim::soaGroups(joints));
    std::vector<std::uint16_t> cursors(3u * joints, 0u);
    std::vector<anim::Affine> world(joints);
    std::vector<gpu::BoneRows> palette(joints);
    anim::SoaSamplingJob{&library, model, clip, time, cursors, pose}.run();
    anim::SoaPaletteJob{&library, model, anim::placementAffine(glm::vec3(0.0f), 0.0f, 1.0f), pose, world, palette}.run();
    return {world[joint].row0.w, world[joint].row1.w, world[joint].row2.w};
}

struct EventTables {
    std::vector<glm::uvec2> ranges;  // per library clip: first event, count
    std::vector<gpu::AnimationEvent> events;
};

EventTables eventTables(const crowd::Crowd& crowd) {
    const anim::ClipLibrary& library = crowd.library();
    EventTables tables;
    tables.ranges.resize(library.clips().size(), glm::uvec2(0u));
    for (std::uint32_t m = 0; m < crowd.models().size(); ++m) {
        const model::SkinnedModel& model = crowd.model(m);
        const std::vector<std::vector<std::int32_t>> pairKeys = crowd::eventPairKeys(model.clips);
        for (std::uint32_t clip = 0; clip < library.clipCount(m); ++clip) {
            const std::vector<anim::ClipEvent>& events = model.clips[clip].events;
            const float duration = library.duration(m, clip);
            // A clip of no length never advances its phase (crowd/events.cpp fires nothing): no events.
            if (!(duration > 0.0f)) continue;
            tables.ranges[library.clipIndex(m, clip)] = glm::uvec2(tables.events.size(), events.size());
            for (std::uint32_t e = 0; e < events.size(); ++e) {
                const anim::ClipEvent& event = events[e];
                // The point in the cycle as the CPU computes it (in double, then rounded once).
                const auto point = static_cast<float>(static_cast<double>(event.time) / duration);
                const glm::vec3 place = event.joint >= 0
                                            ? jointInClip(library, m, clip, point * duration, static_cast<std::uint32_t>(event.joint))
                                            : glm::vec3(0.0f);
                tables.events.push_back({glm::vec4(point, static_cast<float>(event.joint), static_cast<float>(e),
                                                   static_cast<float>(pairKeys[clip][e])),
                                         glm::vec4(place, 0.0f)});
            }
        }
    }
    return tables;
}

template <typename T>
gpu::Buffer upload(const gpu::VulkanContext& context, std::vector<T> table, const char* what) {
    if (table.empty()) table.emplace_back();  // buffers cannot be empty
    return gpu::createBufferWithData(context, std::as_bytes(std::span(table)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, what);
}

// Characters replanned inside one frame's window whose previous segments a frame's table holds: at
// most the crowd or the event capacity, and never more than 65,536 (6 MiB a table, within every
// device's storage-buffer range).
constexpr std::uint32_t kMostPreviousSegments = 65536;
std::uint32_t previousCapacityFor(const crowd::Crowd& crowd, std::uint32_t capacity) {
    return std::max(1u, std::min({crowd.size(), capacity, kMostPreviousSegments}));
}

}  // namespace

namespace {

// The most changed characters' starts a frame scatters (256 KiB of indices a frame slot; a milling
// crowd of 1,000,000 replans about 10,000 a frame); a frame with more (an epoch restates everyone)
// restages every start and copies them in one region. Fixed past 65,536 characters, so memory per
// character stays linear in the crowd.
constexpr std::uint32_t kMostScatteredStarts = 65536;
// Storage-buffer offsets are aligned to at most 256 bytes (minStorageBufferOffsetAlignment's limit).
constexpr VkDeviceSize kOffsetAlignment = 256;

std::uint32_t scatterCapacityFor(const crowd::Crowd& crowd) { return std::min(kMostScatteredStarts, std::max(1u, crowd.size())); }

VkDeviceSize alignedUp(VkDeviceSize bytes) { return (bytes + kOffsetAlignment - 1) / kOffsetAlignment * kOffsetAlignment; }

// A frame slot's upload of starts: the scattered ones' indices, then the starts (the changed ones', or
// every character's in place). Indices first: the starts' offset does not move with the crowd's size.
VkDeviceSize startsOffsetFor(const crowd::Crowd& crowd) { return alignedUp(VkDeviceSize{scatterCapacityFor(crowd)} * sizeof(std::uint32_t)); }

VkDeviceSize startStagingBytes(const crowd::Crowd& crowd) {
    return startsOffsetFor(crowd) + std::max(1u, crowd.size()) * sizeof(float);
}

}  // namespace

std::uint64_t EventPass::bytesFor(const crowd::Crowd& crowd, std::uint32_t capacity, std::uint32_t framesInFlight) {
    // The tables eventTables builds: the events of clips that have a length.
    std::uint64_t events = 0;
    for (std::uint32_t m = 0; m < crowd.models().size(); ++m)
        for (std::uint32_t clip = 0; clip < crowd.library().clipCount(m); ++clip)
            if (crowd.library().duration(m, clip) > 0.0f) events += crowd.model(m).clips[clip].events.size();
    return std::max<std::uint64_t>(1, crowd.library().clips().size()) * sizeof(glm::uvec2) +
           std::max<std::uint64_t>(1, events) * sizeof(gpu::AnimationEvent) + sizeof(gpu::EventHeader) +
           std::uint64_t{capacity} * sizeof(gpu::EventRecord) +
           std::uint64_t{framesInFlight} * previousCapacityFor(crowd, capacity) * sizeof(gpu::PreviousSegment) +
           std::max(1u, crowd.size()) * sizeof(float) + std::uint64_t{framesInFlight} * startStagingBytes(crowd);
}

EventPass::EventPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const AnimationPass& animation,
                     const CrowdBuffers& buffers, const DrawLists& lists, const TerrainBuffer& terrain,
                     std::uint32_t framesInFlight, std::uint32_t capacity)
    : context_(context),
      capacity_(capacity),
      previousCapacity_(previousCapacityFor(crowd, capacity)) {
    try {
        EventTables tables = eventTables(crowd);
        clipEvents_ = upload(context, std::move(tables.ranges), "event ranges");
        eventTable_ = upload(context, std::move(tables.events), "clip events");
        events_ = gpu::createBuffer(context, sizeof(gpu::EventHeader) + std::uint64_t{capacity} * sizeof(gpu::EventRecord),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    gpu::MemoryUse::DeviceLocal, "event buffer");
        const VkDeviceSize startBytes = std::max(1u, crowd.size()) * sizeof(float);
        startsOffset_ = startsOffsetFor(crowd);
        scatterCapacity_ = scatterCapacityFor(crowd);
        segmentStarts_ = gpu::createBuffer(context, startBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           gpu::MemoryUse::DeviceLocal, "segment starts (events)");
        constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            startStaging_.push_back(gpu::createBuffer(context, startStagingBytes(crowd),
                                                      VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                      gpu::MemoryUse::HostUpload, "segment starts (events, upload)"));
            const gpu::BufferBinding scatterBindings[] = {
                {storage, startStaging_.back().buffer, startsOffset_, startBytes},
                {storage, startStaging_.back().buffer, 0, VkDeviceSize{scatterCapacity_} * sizeof(std::uint32_t)},
                {storage, segmentStarts_.buffer}};
            scatterSets_.push_back(std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, scatterBindings));
            previous_.push_back(gpu::createBuffer(context, previousCapacity_ * sizeof(gpu::PreviousSegment),
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::HostUpload,
                                                  "previous segments (events)"));
            const gpu::BufferBinding bindings[] = {
                {storage, animation.libraryBuffer(AnimationPass::Table::Models).buffer},
                {storage, animation.libraryBuffer(AnimationPass::Table::Clips).buffer},
                {storage, animation.libraryBuffer(AnimationPass::Table::RootSamples).buffer},
                {storage, animation.motions().buffer},
                {storage, buffers.characters().buffer},
                {storage, lists.shadowStates().buffer},
                {storage, clipEvents_.buffer},
                {storage, eventTable_.buffer},
                {storage, previous_.back().buffer},
                {storage, segmentStarts_.buffer},
                {storage, events_.buffer},
                {storage, terrain.buffer().buffer}};
            sets_.push_back(std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, bindings));
        }
        const VkDescriptorSetLayout setLayout = sets_.front()->layout();
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::EventPush)};
        layout_ = gpu::createPipelineLayout(context, {&setLayout, 1}, {&push, 1});
        pipeline_ = gpu::createComputePipeline(context, events_comp_spv, layout_, {});
        const VkDescriptorSetLayout scatterLayout = scatterSets_.front()->layout();
        const VkPushConstantRange scatterPush{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::MotionPush)};
        scatterLayout_ = gpu::createPipelineLayout(context, {&scatterLayout, 1}, {&scatterPush, 1});
        scatter_ = gpu::createComputePipeline(context, event_starts_scatter_comp_spv, scatterLayout_, {});
    } catch (...) {
        release();
        throw;
    }
}

EventPass::~EventPass() { release(); }

void EventPass::release() {
    for (VkPipeline pipeline : {pipeline_, scatter_})
        if (pipeline) vkDestroyPipeline(context_.device, pipeline, nullptr);
    for (VkPipelineLayout layout : {layout_, scatterLayout_})
        if (layout) vkDestroyPipelineLayout(context_.device, layout, nullptr);
    pipeline_ = scatter_ = VK_NULL_HANDLE;
    layout_ = scatterLayout_ = VK_NULL_HANDLE;
    sets_.clear();
    scatterSets_.clear();
    for (gpu::Buffer& b : previous_) gpu::destroyBuffer(context_, b);
    previous_.clear();
    for (gpu::Buffer& b : startStaging_) gpu::destroyBuffer(context_, b);
    startStaging_.clear();
    gpu::destroyBuffer(context_, segmentStarts_);
    gpu::destroyBuffer(context_, events_);
    gpu::destroyBuffer(context_, eventTable_);
    gpu::destroyBuffer(context_, clipEvents_);
}

VkDeviceSize EventPass::bytes() const {
    VkDeviceSize total = clipEvents_.size + eventTable_.size + events_.size + segmentStarts_.size;
    for (const gpu::Buffer& b : previous_) total += b.size;
    for (const gpu::Buffer& b : startStaging_) total += b.size;
    return total;
}

VkDeviceSize EventPass::characterBytes() const {
    VkDeviceSize total = segmentStarts_.size;
    for (const gpu::Buffer& b : startStaging_) total += b.size;
    return total;
}

std::uint32_t EventPass::stagePrevious(std::uint32_t frameSlot, const crowd::Crowd& crowd, double from,
                                       std::uint32_t& lost) {
    // The crowd lists whom its last advance replanned (everyone when it entered a new epoch); after
    // more than one advance since the last frame, look at everyone.
    const std::uint64_t generation = crowd.generation();
    const bool seen = seenGeneration_ != kNothing;
    const bool oneAdvance = seen && generation == seenGeneration_ + 1;
    const bool noAdvance = seen && generation == seenGeneration_;
    seenGeneration_ = generation;
    lost = 0;
    if (noAdvance) return 0;
    auto* table = static_cast<gpu::PreviousSegment*>(previous_[frameSlot].mapped);
    std::uint32_t count = 0;
    const double epoch = crowd.epoch();
    auto consider = [&](std::uint32_t c) {
        // Replanned after `from`: what it did before, from what the crowd still knows
        // (Crowd::knownFrom) to that start, is its previous segment.
        const crowd::Segment& current = crowd.plans()[c];
        const double knownFrom = crowd.knownFrom(c);
        if (!crowd.alive(c) || !(current.start > from) || std::isinf(knownFrom) || !(knownFrom < current.start)) return;
        if (count == previousCapacity_) return void(++lost);
        const std::uint32_t model = crowd.characters()[c].model;
        table[count++] = {crowd::recordFrom(crowd.previousPlan(c), epoch, crowd.library(), model),
                          glm::vec4(static_cast<float>(knownFrom - epoch), static_cast<float>(current.start - epoch), 0.0f, 0.0f),
                          glm::uvec4(c, 0u, 0u, 0u)};
    };
    if (oneAdvance) {
        for (std::uint32_t c : crowd.lastChanged()) consider(c);
    } else {
        for (std::uint32_t c = 0; c < crowd.size(); ++c) consider(c);
    }
    return count;
}

void EventPass::uploadStarts(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since) {
    auto* indices = static_cast<std::uint32_t*>(startStaging_[frameSlot].mapped);
    auto* starts = reinterpret_cast<float*>(static_cast<std::byte*>(startStaging_[frameSlot].mapped) + startsOffset_);
    const double epoch = crowd.epoch();
    // When a character's current segment starts: for one spawned after it, its birth (it fired nothing before).
    auto startOf = [&](std::uint32_t c) {
        return static_cast<float>(std::max(crowd.plans()[c].start, crowd.bornAt(c)) - epoch);
    };
    // A few changed characters: their starts and indices, scattered; everyone (or more than the
    // scatter holds): every start in place, one copy.
    std::uint32_t staged = 0;
    const bool everyone = crowd.changes().pendingSince(since) > scatterCapacity_ ||
                          !crowd.changes().forEachSince(since, [&](std::uint32_t c) {
                              starts[staged] = startOf(c);
                              indices[staged++] = c;
                          });
    if (everyone)
        for (std::uint32_t c = 0; c < crowd.size(); ++c) starts[c] = startOf(c);
    if (!everyone && staged == 0) return;
    // The last frames' event passes are done reading the starts this overwrites, and the last copy or
    // scatter is done writing them.
    constexpr gpu::Access copyWrite{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    constexpr gpu::Access computeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const gpu::Access writer = everyone ? copyWrite : computeWrite;
    gpu::memoryBarrier(cmd,
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                            VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       writer);
    if (everyone) {
        const VkBufferCopy all{startsOffset_, 0, VkDeviceSize{crowd.size()} * sizeof(float)};
        vkCmdCopyBuffer(cmd, startStaging_[frameSlot].buffer, segmentStarts_.buffer, 1, &all);
    } else {
        const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
        const gpu::MotionPush push{glm::uvec4(staged, 0u, 0u, 0u), glm::vec4(0.0f)};
        const VkDescriptorSet set = scatterSets_[frameSlot]->set();
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatterLayout_, 0, 1, &set, 0, nullptr);
        vkCmdPushConstants(cmd, scatterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatter_);
        vkCmdDispatch(cmd, groupsFor(staged, maxGroups), 1, 1);
    }
    gpu::memoryBarrier(cmd, writer, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
}

void EventPass::record(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since,
                       double time) {
    // The window: since the previous frame; nothing on the first frame or when time goes back.
    const double from = started_ && previousTime_ <= time ? previousTime_ : time;
    started_ = true;
    previousTime_ = time;
    uploadStarts(cmd, frameSlot, crowd, since);
    std::uint32_t lost = 0;
    const std::uint32_t previousCount = stagePrevious(frameSlot, crowd, from, lost);

    // The host's readers of the last frame's events (any stage) and the last event pass's writes are
    // done before the header is reset.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const gpu::EventHeader header{0u, 0u, capacity_, lost};
    vkCmdUpdateBuffer(cmd, events_.buffer, 0, sizeof header, &header);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT}, kComputeWrite);

    const double epoch = crowd.epoch();
    const glm::vec4 window(static_cast<float>(from - epoch), static_cast<float>(time - epoch), 0.0f, 0.0f);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    const VkDescriptorSet set = sets_[frameSlot]->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    auto dispatch = [&](std::uint32_t items, std::uint32_t previousTable) {
        const std::uint32_t groups = groupsFor(items, maxGroups);
        const gpu::EventPush push{glm::uvec4(items, groups * CULL_WORKGROUP_SIZE, previousTable, 0u), window};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cmd, groups, 1, 1);
    };
    if (from < time) {
        dispatch(crowd.size(), 0u);
        if (previousCount > 0) {
            gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);  // both append to the same buffer
            dispatch(previousCount, 1u);
        }
    }
    // Hosts read the buffer in any stage after recordCompute (their own passes, copies).
    gpu::memoryBarrier(cmd, kComputeWrite, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
}

}  // namespace render
