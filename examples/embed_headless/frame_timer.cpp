#include "frame_timer.hpp"

#include <stdexcept>

namespace {

std::uint32_t timestampBits(VkPhysicalDevice physicalDevice, std::uint32_t queueFamily) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &count, families.data());
    return queueFamily < count ? families[queueFamily].timestampValidBits : 0;
}

}  // namespace

FrameTimer::FrameTimer(VkPhysicalDevice physicalDevice, VkDevice device, std::uint32_t queueFamily,
                       std::uint32_t frameSlots)
    : device_(device), validBits_(timestampBits(physicalDevice, queueFamily)), marks_(frameSlots) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    nanosecondsPerTick_ = properties.limits.timestampPeriod;
    if (nanosecondsPerTick_ <= 0.0) validBits_ = 0;
    if (!available()) return;
    for (std::uint32_t slot = 0; slot < frameSlots; ++slot) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = kMaxMarks;
        VkQueryPool pool;
        if (vkCreateQueryPool(device_, &info, nullptr, &pool) != VK_SUCCESS)
            throw std::runtime_error("vkCreateQueryPool failed");
        pools_.push_back(pool);
    }
}

FrameTimer::~FrameTimer() {
    for (VkQueryPool pool : pools_) vkDestroyQueryPool(device_, pool, nullptr);
}

void FrameTimer::begin(VkCommandBuffer cmd, std::uint32_t slot) {
    slot_ = slot;
    marks_[slot].clear();
    if (!available()) return;
    // Reset in the command buffer, before its first write: no host reset feature needed.
    vkCmdResetQueryPool(cmd, pools_[slot], 0, kMaxMarks);
    mark(cmd, "start");
}

void FrameTimer::mark(VkCommandBuffer cmd, const char* part) {
    std::vector<std::string>& marks = marks_[slot_];
    if (!available() || marks.size() >= kMaxMarks) return;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pools_[slot_],
                         static_cast<std::uint32_t>(marks.size()));
    marks.push_back(part);
}

std::vector<PartTime> FrameTimer::read(std::uint32_t slot) const {
    const std::vector<std::string>& marks = marks_[slot];
    if (!available() || marks.size() < 2) return {};
    std::vector<std::uint64_t> ticks(marks.size());
    if (vkGetQueryPoolResults(device_, pools_[slot], 0, static_cast<std::uint32_t>(marks.size()),
                              ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS)
        throw std::runtime_error("vkGetQueryPoolResults failed");
    // Only the low timestampValidBits count; masking the difference keeps a wrap-around right.
    const std::uint64_t mask = validBits_ >= 64 ? ~0ull : (1ull << validBits_) - 1;
    std::vector<PartTime> parts;
    for (std::size_t i = 1; i < marks.size(); ++i)
        parts.push_back({marks[i], static_cast<double>((ticks[i] - ticks[i - 1]) & mask) * nanosecondsPerTick_ * 1e-6});
    return parts;
}
