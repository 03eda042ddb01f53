#include "app/gpu_timer.h"

#include "app/host_device.h"
#include "app/error.h"

namespace app {

const char* passClockName(PassClock clock) {
    return clock == PassClock::TimestampQueries ? "timestamp queries" : "fence wall clock";
}

GpuTimer::GpuTimer(const HostDevice& context, std::uint32_t framesInFlight, PassClock clock, std::uint32_t maxMarks)
    : context_(context),
      clock_(clock),
      fenceTimes_(framesInFlight),
      names_(framesInFlight),
      maxMarks_(maxMarks),
      periodNs_(context.timestampPeriodNs()) {
    if (clock_ == PassClock::FenceWallClock) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        CHECK_VK(vkCreateFence(context.device, &info, nullptr, &fence_));
        return;
    }
    if (!available()) return;
    for (std::uint32_t i = 0; i < framesInFlight; ++i) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = maxMarks;
        VkQueryPool pool = VK_NULL_HANDLE;
        CHECK_VK(vkCreateQueryPool(context.device, &info, nullptr, &pool));
        pools_.push_back(pool);
    }
}

GpuTimer::~GpuTimer() {
    if (fence_) vkDestroyFence(context_.device, fence_, nullptr);
    for (VkQueryPool pool : pools_) vkDestroyQueryPool(context_.device, pool, nullptr);
}

void GpuTimer::begin(VkCommandBuffer cmd, std::uint32_t frameSlot) {
    slot_ = frameSlot;
    names_[slot_].clear();
    fenceTimes_[slot_].clear();
    if (clock_ == PassClock::FenceWallClock) return;
    if (!available()) return;
    vkCmdResetQueryPool(cmd, pools_[slot_], 0, maxMarks_);
    mark(cmd, "start");
}

void GpuTimer::markByFence(VkCommandBuffer cmd, const std::string& pass) {
    CHECK_VK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    const auto start = std::chrono::steady_clock::now();
    CHECK_VK(vkQueueSubmit(context_.queue, 1, &submit, fence_));
    CHECK_VK(vkWaitForFences(context_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
    const auto end = std::chrono::steady_clock::now();
    CHECK_VK(vkResetFences(context_.device, 1, &fence_));
    fenceTimes_[slot_].push_back({pass, std::chrono::duration<double, std::milli>(end - start).count()});
    // The work is done, so the same command buffer can take the rest of the frame.
    CHECK_VK(vkResetCommandBuffer(cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    CHECK_VK(vkBeginCommandBuffer(cmd, &begin));
}

void GpuTimer::mark(VkCommandBuffer cmd, const std::string& pass) {
    if (clock_ == PassClock::FenceWallClock) return markByFence(cmd, pass);
    if (!available() || names_[slot_].size() >= maxMarks_) return;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[slot_],
                         static_cast<std::uint32_t>(names_[slot_].size()));
    names_[slot_].push_back(pass);
}

std::vector<PassTime> GpuTimer::results(std::uint32_t frameSlot) const {
    if (clock_ == PassClock::FenceWallClock) return fenceTimes_[frameSlot];
    const std::vector<std::string>& names = names_[frameSlot];
    if (!available() || names.size() < 2) return {};
    std::vector<std::uint64_t> ticks(names.size());
    CHECK_VK(vkGetQueryPoolResults(context_.device, pools_[frameSlot], 0, static_cast<std::uint32_t>(names.size()),
                                   ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<PassTime> passes;
    for (std::size_t i = 1; i < names.size(); ++i)
        passes.push_back({names[i], static_cast<double>(ticks[i] - ticks[i - 1]) * periodNs_ * 1e-6});
    return passes;
}

}  // namespace app
