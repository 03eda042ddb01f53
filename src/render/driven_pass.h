#pragma once
// Characters the host drives, on the GPU (docs/host-driven.md): each slot's ring of keys and its key
// count, and the models' gait table, which the motion pass reads (shaders/motion.comp.glsl). Keys come
// two ways: those the CPU made of samples in the host's memory (crowd::Crowd::drive) are uploaded as
// they come, a slot's new keys alone; the host's own pass may instead write one sample per slot into a
// buffer of its own each frame, which the ingest pass makes into keys on the GPU, with the same rules
// (shaders/driven_keys.h).
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "render/crowd_buffers.h"

namespace gpu { class VulkanContext; }

namespace render {

// The host's buffer of samples for this frame: one gpu::DeviceSample per slot from `offset`, `size`
// bytes of it readable. The host's pass wrote it before the renderer's recordCompute and made the writes
// visible to compute-shader storage reads.
struct DeviceSampleInput {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
};

// What the ingest pass did with the device samples in a frame.
struct IngestTally {
    std::uint32_t applied = 0, late = 0, refused = 0;
};

class DrivenPass {
public:
    DrivenPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const CrowdBuffers& buffers,
               const gpu::Buffer& motions, std::uint32_t framesInFlight);
    ~DrivenPass();
    DrivenPass(const DrivenPass&) = delete;
    DrivenPass& operator=(const DrivenPass&) = delete;

    // Device bytes of a crowd's slots with `keysPerSlot` keys and `models` models, and of the frames'
    // staging (with room for kLeastUploads keys' uploads; more grow with the keys a frame carries).
    static constexpr std::size_t kLeastUploads = 256;
    static std::uint64_t bytesFor(std::uint32_t slots, std::uint32_t keysPerSlot, std::uint32_t models,
                                  std::uint32_t framesInFlight);

    // Uploads the models' gait table, and the keys the CPU made after
    // generation `since` (every host-driven slot's ring for crowd::ChangeLog::kEverything). Before the
    // motion pass, after the segments' upload (which sets a changed slot's key count).
    void recordUpload(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since);
    // Throws gpu::Error for samples the ingest cannot read: no buffer, one smaller than the slots'
    // samples, an offset off the storage alignment, a crowd without driven keys.
    void checkSamples(const DeviceSampleInput& samples) const;
    // The device samples made into keys, for a frame at `time` (checkSamples first).
    void recordIngest(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd,
                      const DeviceSampleInput& samples, double time);
    // The ingest's counts of the slot's last frame (read after its fence).
    IngestTally tally(std::uint32_t frameSlot) const;

    std::uint32_t keysPerSlot() const { return keysPerSlot_; }
    const gpu::Buffer& keys() const { return keys_; }
    const gpu::Buffer& heads() const { return heads_; }
    const gpu::Buffer& owners() const { return owners_; }
    const gpu::Buffer& models() const { return models_; }
    VkDeviceSize bytes() const;

private:
    void release();
    // Room for `entries` key uploads in the slot's staging (made again, larger, when short).
    void reserveUploads(std::uint32_t frameSlot, std::size_t entries);

    const gpu::VulkanContext& context_;
    std::uint32_t slots_, keysPerSlot_;
    // The keys, each slot's key count, the generation of the character whose keys a device-driven slot
    // holds (shaders/driven_ingest.comp.glsl), and the gait table.
    gpu::Buffer keys_, heads_, owners_, models_;
    struct Staging {
        gpu::Buffer uploads, models;
        gpu::Buffer tally, tallyRead;  // the ingest's counts on the device, and copied for the host
        std::size_t capacity = 0;  // key uploads `uploads` holds
        std::unique_ptr<gpu::DescriptorBundle> scatterSet;
        std::unique_ptr<gpu::DescriptorBundle> ingestSet;
        VkBuffer ingestSamples = VK_NULL_HANDLE;  // the host buffer ingestSet points at
        VkDeviceSize ingestOffset = 0;
    };
    std::vector<Staging> staging_;
    const CrowdBuffers& buffers_;
    const gpu::Buffer& motions_;
    VkPipelineLayout scatterLayout_ = VK_NULL_HANDLE, ingestLayout_ = VK_NULL_HANDLE;
    VkPipeline scatter_ = VK_NULL_HANDLE, ingest_ = VK_NULL_HANDLE;
};

}  // namespace render
