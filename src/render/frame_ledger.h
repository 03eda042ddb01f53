#pragma once
// Which crowd changes a frame uploads when the host may drop frames. A frame recorded but never
// submitted (a swapchain out of date, an exception in the host's own code) loses the uploads it
// carried, and the renderer uploads only what changed since: so every frame writes a number of its own
// into a host-visible word of its frame slot, and when the slot comes round again (the host has waited
// for it) a word that does not hold that number says the frame never ran. The frame then uploads again
// every change since the one the lost frame started from (render::AnimationPass, render::EventPass take
// the same generation). Frames of other slots still in flight count as run; if one of them is lost
// instead, its slot finds out when it comes round (a picture or two late, never for good).
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"

namespace gpu { class VulkanContext; }

namespace render {

class FrameLedger {
public:
    FrameLedger(const gpu::VulkanContext& context, std::uint32_t framesInFlight);
    ~FrameLedger();
    FrameLedger(const FrameLedger&) = delete;
    FrameLedger& operator=(const FrameLedger&) = delete;

    // What a frame uploads: the crowd's changes after generation `since` (crowd::ChangeLog::kEverything:
    // every slot), and with `resend`, what uploads on change alone (the terrain) again: a frame was lost,
    // or the crowd is another.
    struct Uploads {
        std::uint64_t since;
        bool resend;
    };
    // At the start of a frame in `slot`, after the crowd's changes were sealed up to `sealed`. A crowd
    // other than the last one seen (`crowdId`) is uploaded whole. Records the write of this frame's number.
    Uploads begin(VkCommandBuffer cmd, std::uint32_t slot, std::uint64_t crowdId, std::uint64_t sealed);
    // Frames found lost so far (tests and reports).
    std::uint64_t framesLost() const { return lost_; }

private:
    struct SlotFrame {
        std::uint32_t number = 0;  // 0: nothing recorded in the slot yet (the words start at 0)
        std::uint64_t from = 0;    // the generation that frame uploaded changes after
    };
    const gpu::VulkanContext& context_;
    gpu::Buffer words_;  // one uint per slot, written by each frame
    std::vector<SlotFrame> slots_;
    std::uint32_t next_ = 0;
    std::uint64_t through_;  // the generation the last frame recorded uploaded through
    std::uint64_t crowdId_ = 0;
    std::uint64_t lost_ = 0;
};

}  // namespace render
