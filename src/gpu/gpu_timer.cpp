#include "gpu/gpu_timer.h"

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace gpu {

GpuTimer::GpuTimer(const VulkanContext& context, std::uint32_t framesInFlight, std::uint32_t maxMarks)
    : context_(context), names_(framesInFlight), maxMarks_(maxMarks), periodNs_(context.timestampPeriodNs()) {
    if (!available()) return;
    for (std::uint32_t i = 0; i < framesInFlight; ++i) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = maxMarks;
        VkQueryPool pool = VK_NULL_HANDLE;
        VK_CHECK(vkCreateQueryPool(context.device, &info, nullptr, &pool));
        pools_.push_back(pool);
    }
}

GpuTimer::~GpuTimer() {
    for (VkQueryPool pool : pools_) vkDestroyQueryPool(context_.device, pool, nullptr);
}

void GpuTimer::begin(VkCommandBuffer cmd, std::uint32_t frameSlot) {
    slot_ = frameSlot;
    names_[slot_].clear();
    if (!available()) return;
    vkCmdResetQueryPool(cmd, pools_[slot_], 0, maxMarks_);
    mark(cmd, "start");
}

void GpuTimer::mark(VkCommandBuffer cmd, const std::string& pass) {
    if (!available() || names_[slot_].size() >= maxMarks_) return;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[slot_],
                         static_cast<std::uint32_t>(names_[slot_].size()));
    names_[slot_].push_back(pass);
}

std::vector<PassTime> GpuTimer::results(std::uint32_t frameSlot) const {
    const std::vector<std::string>& names = names_[frameSlot];
    if (!available() || names.size() < 2) return {};
    std::vector<std::uint64_t> ticks(names.size());
    VK_CHECK(vkGetQueryPoolResults(context_.device, pools_[frameSlot], 0, static_cast<std::uint32_t>(names.size()),
                                   ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<PassTime> passes;
    for (std::size_t i = 1; i < names.size(); ++i)
        passes.push_back({names[i], static_cast<double>(ticks[i] - ticks[i - 1]) * periodNs_ * 1e-6});
    return passes;
}

}  // namespace gpu
