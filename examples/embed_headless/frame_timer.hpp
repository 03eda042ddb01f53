// GPU time of the parts of a frame, measured the way crowdgpu's programs measure theirs: a timestamp
// written once every earlier command of the frame has finished (vkCmdWriteTimestamp2 at
// ALL_COMMANDS) at the start of the frame and at the end of each part; a part's time is the
// difference between its mark and the one before. The queries stay in the frame's own command
// buffer, so frames stay pipelined (no wait per part). One query pool per frame slot, read once the
// slot's fence has signalled.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct PartTime {
    std::string part;
    double milliseconds;
};

class FrameTimer {
public:
    FrameTimer(VkPhysicalDevice physicalDevice, VkDevice device, std::uint32_t queueFamily, std::uint32_t frameSlots);
    ~FrameTimer();
    FrameTimer(const FrameTimer&) = delete;
    FrameTimer& operator=(const FrameTimer&) = delete;

    // False when the queue writes no timestamps: every call below then does nothing.
    bool available() const { return validBits_ > 0; }
    // Starts the slot's marks in its command buffer (resets its queries) with the mark "start".
    void begin(VkCommandBuffer cmd, std::uint32_t slot);
    // Ends the part named `part` here. Marks past the pool's size are dropped.
    void mark(VkCommandBuffer cmd, const char* part);
    // The slot's parts in the order they were marked; call after the slot's fence has signalled.
    std::vector<PartTime> read(std::uint32_t slot) const;

private:
    static constexpr std::uint32_t kMaxMarks = 16;  // more than the renderer's passes and the host's

    VkDevice device_;
    double nanosecondsPerTick_;
    std::uint32_t validBits_;
    std::vector<VkQueryPool> pools_;                 // one per frame slot
    std::vector<std::vector<std::string>> marks_;    // per slot: the names of the marks written
    std::uint32_t slot_ = 0;                         // the slot being recorded
};
