#include "render/driven_pass.h"

#include <algorithm>
#include <cstring>

#include "crowd/epoch.h"
#include "crowd/worker_pool.h"
#include "driven_ingest.comp.spv.h"
#include "driven_keys_scatter.comp.spv.h"
#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {
namespace {

constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr gpu::Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The ingest set's bindings (shaders/driven_ingest.comp.glsl): the host's samples, the tally.
constexpr std::uint32_t kSamplesBinding = 5;

std::uint32_t groupsFor(std::uint64_t items, std::uint32_t maxGroups) {
    return static_cast<std::uint32_t>(
        std::clamp<std::uint64_t>((items + CULL_WORKGROUP_SIZE - 1) / CULL_WORKGROUP_SIZE, 1, maxGroups));
}

}  // namespace

// A crowd made without driven keys keeps one of each (buffers cannot be empty); the passes read none. Each
// frame slot stages the gait table, reads back its tally and keeps room for kLeastUploads keys' uploads
// (more only while a frame carries more keys: that growth is not counted).
std::uint64_t DrivenPass::bytesFor(std::uint32_t slots, std::uint32_t keysPerSlot, std::uint32_t models,
                                   std::uint32_t framesInFlight) {
    const std::uint64_t n = keysPerSlot > 0 ? std::max(slots, 1u) : 1u;
    const std::uint64_t gaits = std::max(models, 1u) * sizeof(gpu::DrivenModel);
    return n * std::max(keysPerSlot, 1u) * sizeof(gpu::DrivenKey) + 2 * n * sizeof(std::uint32_t) + gaits +
           std::uint64_t{framesInFlight} * (gaits + 2 * sizeof(glm::uvec4) + kLeastUploads * sizeof(gpu::DrivenKeyUpload));
}

DrivenPass::DrivenPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const CrowdBuffers& buffers,
                       const gpu::Buffer& motions, std::uint32_t framesInFlight)
    : context_(context),
      slots_(std::max(crowd.size(), 1u)),
      keysPerSlot_(crowd.drivenKeysPerSlot()),
      buffers_(buffers),
      motions_(motions) {
    try {
        const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        const std::uint32_t rings = keysPerSlot_ > 0 ? slots_ : 1u;  // without keys: one of each, never read
        keys_ = gpu::createBuffer(context, std::uint64_t{rings} * std::max(keysPerSlot_, 1u) * sizeof(gpu::DrivenKey),
                                  usage, gpu::MemoryUse::DeviceLocal, "driven keys");
        // Zeroed: no slot has a key, and no character owns a ring (generations start at 1).
        const std::vector<std::uint32_t> zeros(rings, 0u);
        heads_ = gpu::createBufferWithData(context, std::as_bytes(std::span(zeros)), usage, "driven key counts");
        owners_ = gpu::createBufferWithData(context, std::as_bytes(std::span(zeros)), usage, "driven key owners");
        models_ = gpu::createBuffer(context, std::max<std::size_t>(crowd.models().size(), 1) * sizeof(gpu::DrivenModel),
                                    usage, gpu::MemoryUse::DeviceLocal, "driven gaits");
        for (std::uint32_t i = 0; i < framesInFlight; ++i) {
            Staging& s = staging_.emplace_back();
            s.models = gpu::createBuffer(context, models_.size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::HostUpload,
                                         "driven gaits (upload)");
            s.tally = gpu::createBuffer(context, sizeof(glm::uvec4),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                        gpu::MemoryUse::DeviceLocal, "driven ingest tally");
            s.tallyRead = gpu::createBuffer(context, sizeof(glm::uvec4), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            gpu::MemoryUse::HostReadback, "driven ingest tally (readback)");
            std::memset(s.tallyRead.mapped, 0, sizeof(glm::uvec4));
            // The samples' binding points at the key counts until the host gives its buffer.
            const gpu::BufferBinding ingest[] = {{kStorage, motions.buffer},       {kStorage, buffers.characters().buffer},
                                                 {kStorage, models_.buffer},       {kStorage, keys_.buffer},
                                                 {kStorage, heads_.buffer},        {kStorage, heads_.buffer},
                                                 {kStorage, s.tally.buffer},       {kStorage, owners_.buffer}};
            s.ingestSet = std::make_unique<gpu::DescriptorBundle>(context, VK_SHADER_STAGE_COMPUTE_BIT, ingest);
            reserveUploads(i, 1);
        }
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(gpu::MotionPush)};
        const VkDescriptorSetLayout scatterSetLayout = staging_.front().scatterSet->layout();
        scatterLayout_ = gpu::createPipelineLayout(context, {&scatterSetLayout, 1}, {&push, 1});
        scatter_ = gpu::createComputePipeline(context, driven_keys_scatter_comp_spv, scatterLayout_, {});
        const VkDescriptorSetLayout ingestSetLayout = staging_.front().ingestSet->layout();
        ingestLayout_ = gpu::createPipelineLayout(context, {&ingestSetLayout, 1}, {&push, 1});
        ingest_ = gpu::createComputePipeline(context, driven_ingest_comp_spv, ingestLayout_, {});
    } catch (...) {
        release();
        throw;
    }
}

DrivenPass::~DrivenPass() { release(); }

void DrivenPass::release() {
    for (VkPipeline* p : {&scatter_, &ingest_}) {
        if (*p) vkDestroyPipeline(context_.device, *p, nullptr);
        *p = VK_NULL_HANDLE;
    }
    for (VkPipelineLayout* l : {&scatterLayout_, &ingestLayout_}) {
        if (*l) vkDestroyPipelineLayout(context_.device, *l, nullptr);
        *l = VK_NULL_HANDLE;
    }
    for (Staging& s : staging_) {
        s.scatterSet.reset();
        s.ingestSet.reset();
        gpu::destroyBuffer(context_, s.uploads);
        gpu::destroyBuffer(context_, s.models);
        gpu::destroyBuffer(context_, s.tally);
        gpu::destroyBuffer(context_, s.tallyRead);
    }
    staging_.clear();
    for (gpu::Buffer* b : {&models_, &owners_, &heads_, &keys_}) gpu::destroyBuffer(context_, *b);
}

VkDeviceSize DrivenPass::bytes() const {
    VkDeviceSize total = keys_.size + heads_.size + owners_.size + models_.size;
    for (const Staging& s : staging_) total += s.uploads.size + s.models.size + s.tally.size + s.tallyRead.size;
    return total;
}

void DrivenPass::reserveUploads(std::uint32_t frameSlot, std::size_t entries) {
    Staging& s = staging_[frameSlot];
    if (entries <= s.capacity && s.scatterSet) return;
    // Grown by half again past the need, so a crowd whose uploads grow a little each frame reallocates rarely.
    const std::size_t capacity = std::max<std::size_t>(entries + entries / 2, kLeastUploads);
    gpu::Buffer uploads = gpu::createBuffer(context_, capacity * sizeof(gpu::DrivenKeyUpload),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::HostUpload,
                                            "driven keys (upload)");
    s.scatterSet.reset();
    gpu::destroyBuffer(context_, s.uploads);
    s.uploads = uploads;
    s.capacity = capacity;
    const gpu::BufferBinding scatter[] = {{kStorage, s.uploads.buffer}, {kStorage, keys_.buffer}, {kStorage, heads_.buffer}};
    s.scatterSet = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_COMPUTE_BIT, scatter);
}

void DrivenPass::recordUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since) {
    Staging& s = staging_[frameSlot];
    // The gait table goes up every frame (a kilobyte at most): a frame that carried a change and was
    // dropped leaves nothing behind.
    {
        const std::vector<gpu::DrivenModel>& table = crowd.drivenModels();
        std::memcpy(s.models.mapped, table.data(), table.size() * sizeof(gpu::DrivenModel));
        gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                           {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
        const VkBufferCopy copy{0, 0, table.size() * sizeof(gpu::DrivenModel)};
        vkCmdCopyBuffer(cmd, s.models.buffer, models_.buffer, 1, &copy);
        gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                           {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
    }
    const crowd::DrivenKeys& keys = crowd.drivenKeys();
    if (keysPerSlot_ == 0 || keys.empty()) return;
    reserveUploads(frameSlot, crowd.keysSince(since));
    auto* out = static_cast<gpu::DrivenKeyUpload*>(staging_[frameSlot].uploads.mapped);
    std::size_t count = 0;
    // The log's lists staged on every core (a million keys a frame, 48 MB): an entry that is no key
    // now (a late sample's, or one its ring has dropped) goes up as a slot past the crowd, which the
    // scatter skips.
    const bool fromLog = crowd.forEachKeyListSince(since, [&](const crowd::Crowd::KeyLogList& list) {
        gpu::DrivenKeyUpload* to = out + count;
        crowd::WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(list.size()), 4096,
                                                [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t i = begin; i < end; ++i) {
                const auto [slot, index] = list[i];
                to[i] = crowd.keyStillHeld(slot, index)
                            ? gpu::DrivenKeyUpload{keys.key(slot, index), glm::uvec4(slot, index, 0u, 0u)}
                            : gpu::DrivenKeyUpload{gpu::DrivenKey{}, glm::uvec4(crowd::Crowd::kNoKeySlot, 0u, 0u, 0u)};
            }
        });
        count += list.size();
    });
    if (!fromLog)
        for (std::uint32_t slot = 0; slot < crowd.size(); ++slot)
            if (crowd.alive(slot) && crowd.drivenBy(slot) == crowd::Driven::HostSamples)
                for (std::uint32_t k = keys.oldest(slot); k < keys.count(slot); ++k)
                    out[count++] = {keys.key(slot, k), glm::uvec4(slot, k, 0u, 0u)};
    if (count == 0) return;
    // After the segments' scatter (it sets changed slots' key counts), and the last frames' readers.
    gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    const gpu::MotionPush push{glm::uvec4(static_cast<std::uint32_t>(count), slots_, keysPerSlot_, 0u), glm::vec4(0.0f)};
    const VkDescriptorSet set = staging_[frameSlot].scatterSet->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatterLayout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, scatterLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scatter_);
    vkCmdDispatch(cmd, groupsFor(count, maxGroups), 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite, kComputeWrite);
}

void DrivenPass::checkSamples(const DeviceSampleInput& samples) const {
    const VkDeviceSize needed = std::uint64_t{slots_} * sizeof(gpu::DeviceSample);
    if (samples.buffer == VK_NULL_HANDLE || samples.size < needed)
        throw gpu::Error("device samples: the buffer holds " + gpu::formatBytes(samples.buffer ? samples.size : 0) +
                         " from its offset, the " + std::to_string(slots_) + " slots' samples need " +
                         gpu::formatBytes(needed) + " (16 bytes a slot)");
    if (keysPerSlot_ == 0) throw gpu::Error("device samples: the crowd was made without driven keys (give its capacity's drivenKeys)");
    if (samples.offset % context_.properties.limits.minStorageBufferOffsetAlignment != 0)
        throw gpu::Error("device samples: offset " + std::to_string(samples.offset) +
                         " is not a multiple of this device's minStorageBufferOffsetAlignment (" +
                         std::to_string(context_.properties.limits.minStorageBufferOffsetAlignment) + ")");
}

void DrivenPass::recordIngest(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd,
                              const DeviceSampleInput& samples, double time) {
    checkSamples(samples);
    const VkDeviceSize needed = std::uint64_t{slots_} * sizeof(gpu::DeviceSample);
    Staging& s = staging_[frameSlot];
    if (s.ingestSamples != samples.buffer || s.ingestOffset != samples.offset) {
        s.ingestSet->rebind(kSamplesBinding, {kStorage, samples.buffer, samples.offset, needed});
        s.ingestSamples = samples.buffer;
        s.ingestOffset = samples.offset;
    }
    std::memset(s.tallyRead.mapped, 0, sizeof(glm::uvec4));  // the slot's last frame is done: read or not
    constexpr gpu::Access transfer{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT};
    gpu::memoryBarrier(cmd, transfer, transfer);
    vkCmdFillBuffer(cmd, s.tally.buffer, 0, VK_WHOLE_SIZE, 0u);
    // The tally cleared, and the last frames' readers of the keys and counts done, before they are written.
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       kComputeWrite);
    const std::uint32_t maxGroups = context_.properties.limits.maxComputeWorkGroupCount[0];
    const std::uint32_t groups = groupsFor(crowd.size(), maxGroups);
    const double epochIndex = crowd.epoch() / crowd::kEpochSeconds;
    const gpu::MotionPush push{glm::uvec4(crowd.size(), groups * CULL_WORKGROUP_SIZE, keysPerSlot_, 0u),
                               glm::vec4(static_cast<float>(time - crowd.epoch()), 0.0f, 0.0f, static_cast<float>(epochIndex))};
    const VkDescriptorSet set = s.ingestSet->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ingestLayout_, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, ingestLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ingest_);
    vkCmdDispatch(cmd, groups, 1, 1);
    gpu::memoryBarrier(cmd, kComputeWrite,
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT});
    const VkBufferCopy copy{0, 0, sizeof(glm::uvec4)};
    vkCmdCopyBuffer(cmd, s.tally.buffer, s.tallyRead.buffer, 1, &copy);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT});
}

IngestTally DrivenPass::tally(std::uint32_t frameSlot) const {
    glm::uvec4 t;
    std::memcpy(&t, staging_[frameSlot].tallyRead.mapped, sizeof t);
    return {t.x, t.y, t.z};
}

}  // namespace render
