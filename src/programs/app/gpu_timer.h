#pragma once
// Per-pass GPU time: a frame writes named marks, the time of a pass is the difference between its
// mark and the previous one. Two clocks:
// - TimestampQueries: vkCmdWriteTimestamp2 after all earlier work; frames stay pipelined.
// - FenceWallClock: each mark ends the command buffer, submits it, waits on a fence and times
//   submit-to-signal on the host, then begins the buffer again. Serializes the frame, but is right
//   on drivers whose timestamps do not bracket the work (lavapipe and compute dispatches).
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

struct PassTime {
    std::string pass;
    double milliseconds;
};

enum class PassClock { TimestampQueries, FenceWallClock };
const char* passClockName(PassClock clock);

class GpuTimer {
public:
    // One query pool per frame in flight, `maxMarks` marks per frame.
    GpuTimer(const HostDevice& context, std::uint32_t framesInFlight, PassClock clock = PassClock::TimestampQueries,
             std::uint32_t maxMarks = 16);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool available() const { return clock_ == PassClock::FenceWallClock || periodNs_ > 0.0; }
    PassClock clock() const { return clock_; }
    // Starts a frame's marks; the first mark is "start".
    void begin(VkCommandBuffer cmd, std::uint32_t frameSlot);
    // Writes a timestamp once all earlier commands have finished; the pass named ends here.
    void mark(VkCommandBuffer cmd, const std::string& pass);
    // The passes of the frame recorded in this slot; call after its fence has signalled.
    std::vector<PassTime> results(std::uint32_t frameSlot) const;

private:
    void markByFence(VkCommandBuffer cmd, const std::string& pass);

    const HostDevice& context_;
    PassClock clock_;
    VkFence fence_ = VK_NULL_HANDLE;
    std::vector<std::vector<PassTime>> fenceTimes_;
    std::vector<VkQueryPool> pools_;
    std::vector<std::vector<std::string>> names_;
    std::uint32_t maxMarks_;
    std::uint32_t slot_ = 0;
    double periodNs_;
};

}  // namespace app
