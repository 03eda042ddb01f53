#pragma once
// Animation events on the GPU (docs/events.md, "The GPU event buffer"): after culling, the clip
// events that characters in view fire in the frame's window (the previous recordCompute's time, this
// one's], appended to one buffer a host consumes in its own passes (particles, sounds read back):
// gpu::EventHeader, then gpu::EventRecord each. The same closed form as crowd::Crowd::events, from
// the clips' event tables uploaded once (where each event falls in its cycle, and its joint's
// model-space position then, from the CPU pose).
//
// In view means the view frustum holds the character's pose sphere (the cull word's
// SHADOW_IN_VIEW_BIT): meshes and impostors alike, shadow casters outside the view not.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/descriptor_bundle.h"
#include "gpu_types.h"

namespace gpu { class VulkanContext; }

namespace render {

class AnimationPass;
class CrowdBuffers;
class DrawLists;
class TerrainBuffer;

// Records the event buffer holds unless a host asks otherwise: at 32 bytes each, 2 MiB. A frame of
// 100,000 soldiers in view, walking with a footstep every half second per foot, fires about 6,700 at
// 60 fps; the rest is room for slow frames.
inline constexpr std::uint32_t kDefaultEventCapacity = 65536;

class EventPass {
public:
    // `capacity`: the most records a frame keeps (the rest are counted as dropped); the table of
    // previous segments holds min(crowd size, capacity, 65,536) characters replanned in a frame.
    EventPass(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const AnimationPass& animation,
              const CrowdBuffers& buffers, const DrawLists& lists, const TerrainBuffer& terrain,
              std::uint32_t framesInFlight, std::uint32_t capacity);
    ~EventPass();
    EventPass(const EventPass&) = delete;
    EventPass& operator=(const EventPass&) = delete;

    // Device bytes the pass allocates for this crowd and capacity (the memory planner's figure).
    static std::uint64_t bytesFor(const crowd::Crowd& crowd, std::uint32_t capacity, std::uint32_t framesInFlight);
    // After culling (the cull word's in-view bit) and the motion segments' upload: this frame's
    // events, for the window since the previous call (empty on the first call, and when time goes back).
    // Uploads the segment starts of the slots `crowd` changed after generation `since`
    // (render/frame_ledger.h) first.
    void record(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since,
                double time);

    const gpu::Buffer& events() const { return events_; }
    std::uint32_t capacity() const { return capacity_; }
    VkDeviceSize bytes() const;
    // Of those, what grows with the crowd: the segment starts and their upload (the rest is fixed by
    // the clips and the capacity, the previous-segment table once the crowd passes the capacity).
    VkDeviceSize characterBytes() const;

private:
    // The true starts of the current segments of the slots changed after `since` (their scatter, or a
    // copy of everyone's, into segmentStarts_ recorded).
    void uploadStarts(VkCommandBuffer cmd, std::uint32_t frameSlot, const crowd::Crowd& crowd, std::uint64_t since);
    // The previous segments of the characters the crowd's last advance replanned inside the window,
    // staged for this slot. Returns how many; `lost`: those past the table.
    std::uint32_t stagePrevious(std::uint32_t frameSlot, const crowd::Crowd& crowd, double from, std::uint32_t& lost);
    void release();

    const gpu::VulkanContext& context_;
    std::uint32_t capacity_, previousCapacity_;
    gpu::Buffer clipEvents_, eventTable_, events_;
    // Per character, when its current segment truly starts (s since the epoch, a float): a record
    // restated at the epoch (crowd/segment.h) starts there on paper, but its events before the epoch
    // in a window that crosses it belong to it back to this start.
    gpu::Buffer segmentStarts_;
    std::vector<gpu::Buffer> previous_;  // per frame slot: the replanned characters' previous segments
    // Per frame slot: the scattered characters' indices, then (from startsOffset_) the starts.
    std::vector<gpu::Buffer> startStaging_;
    VkDeviceSize startsOffset_ = 0;
    std::uint32_t scatterCapacity_ = 0;  // the most starts a frame scatters; more: all restaged, one copy
    std::vector<std::unique_ptr<gpu::DescriptorBundle>> sets_;
    std::vector<std::unique_ptr<gpu::DescriptorBundle>> scatterSets_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout scatterLayout_ = VK_NULL_HANDLE;
    VkPipeline scatter_ = VK_NULL_HANDLE;
    bool started_ = false;        // a frame was recorded: previousTime_ holds its time
    double previousTime_ = 0.0;
    static constexpr std::uint64_t kNothing = ~0ull;
    std::uint64_t seenGeneration_ = kNothing;  // the crowd's generation at the last call
};

}  // namespace render
