#include "gpu/vulkan_context.h"

#include <algorithm>
#include <vector>

#include "gpu/setup_queue.h"
#include "gpu/vulkan_error.h"

namespace gpu {
namespace {

DeviceDescription describe(VkPhysicalDevice device) {
    static const char* const typeNames[] = {"other", "integrated", "discrete", "virtual", "cpu"};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &properties);
    const auto type = static_cast<std::size_t>(properties.properties.deviceType);
    return {0, properties.properties.deviceName, type < 5 ? typeNames[type] : "other",
            std::string(driver.driverName) + " " + driver.driverInfo, properties.properties.apiVersion};
}

}  // namespace

VulkanContext::VulkanContext(const BorrowedHandles& borrowed)
    : instance(borrowed.instance),
      physicalDevice(borrowed.physicalDevice),
      device(borrowed.device),
      queue(borrowed.queue),
      queueFamily(borrowed.queueFamily),
      fragmentStores(borrowed.fragmentStoresAndAtomics),
      int64Atomics(borrowed.int64Atomics),
      debugNames_(borrowed.debugNames) {
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
    description = describe(physicalDevice);
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    if (queueFamily < familyCount && families[queueFamily].timestampValidBits > 0)
        timestampPeriodNs_ = properties.limits.timestampPeriod;
    if (!queue) {
        setup_ = std::make_unique<SetupQueue>();
        return;
    }
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
}

VulkanContext::~VulkanContext() {
    setup_.reset();
    if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);  // the only thing it made
}

std::uint64_t VulkanContext::deviceLocalBytes() const {
    std::uint64_t largest = 0;
    for (std::uint32_t i = 0; i < memoryProperties.memoryHeapCount; ++i)
        if (memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            largest = std::max<std::uint64_t>(largest, memoryProperties.memoryHeaps[i].size);
    return largest;
}

void VulkanContext::setDebugName(VkObjectType type, std::uint64_t handle, const char* name) const {
    if (!debugNames_) return;
    auto setName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    setName(device, &info);
}

}  // namespace gpu
