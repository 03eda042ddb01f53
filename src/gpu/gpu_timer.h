#pragma once
// Per-pass GPU time from timestamp queries: a frame writes named marks, the time of a pass is the
// difference between its mark and the previous one.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

struct PassTime {
    std::string pass;
    double milliseconds;
};

class GpuTimer {
public:
    // One query pool per frame in flight, `maxMarks` marks per frame.
    GpuTimer(const VulkanContext& context, std::uint32_t framesInFlight, std::uint32_t maxMarks = 16);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool available() const { return periodNs_ > 0.0; }
    // Starts a frame's marks; the first mark is "start".
    void begin(VkCommandBuffer cmd, std::uint32_t frameSlot);
    // Writes a timestamp once all earlier commands have finished; the pass named ends here.
    void mark(VkCommandBuffer cmd, const std::string& pass);
    // The passes of the frame recorded in this slot; call after its fence has signalled.
    std::vector<PassTime> results(std::uint32_t frameSlot) const;

private:
    const VulkanContext& context_;
    std::vector<VkQueryPool> pools_;
    std::vector<std::vector<std::string>> names_;
    std::uint32_t maxMarks_;
    std::uint32_t slot_ = 0;
    double periodNs_;
};

}  // namespace gpu
