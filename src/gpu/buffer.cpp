#include "gpu/buffer.h"

#include <cstring>

#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace gpu {
namespace {

int findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                   VkMemoryPropertyFlags properties) {
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties)
            return static_cast<int>(i);
    return -1;
}

VkMemoryPropertyFlags propertiesFor(MemoryUse use) {
    switch (use) {
        case MemoryUse::HostUpload: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        case MemoryUse::HostReadback:
            return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                   VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        case MemoryUse::DeviceLocal: break;
    }
    return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
}

}  // namespace

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 4) value /= 1024.0, ++unit;
    char text[32];
    std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
    return text;
}

VkDeviceMemory allocateMemory(const VulkanContext& context, const VkMemoryRequirements& requirements,
                              VkMemoryPropertyFlags properties, const std::string& what) {
    int type = findMemoryType(context.memoryProperties, requirements.memoryTypeBits, properties);
    // Readback prefers cached memory but any host-visible memory will do.
    if (type < 0 && (properties & VK_MEMORY_PROPERTY_HOST_CACHED_BIT))
        type = findMemoryType(context.memoryProperties, requirements.memoryTypeBits,
                              properties & ~VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    if (type < 0) throw Error("no suitable memory type for " + what);
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = static_cast<std::uint32_t>(type);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult result = vkAllocateMemory(context.device, &info, nullptr, &memory);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw Error(std::string(result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "out of device memory" : "out of host memory") +
                    " allocating " + formatBytes(requirements.size) + " for " + what +
                    " (fewer characters or a smaller target need less)");
    VK_CHECK(result);
    return memory;
}

Buffer createBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const std::string& what) {
    Buffer result;
    result.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(context.device, &info, nullptr, &result.buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(context.device, result.buffer, &requirements);
    try {
        result.memory = allocateMemory(context, requirements, propertiesFor(use), what);
    } catch (...) {
        vkDestroyBuffer(context.device, result.buffer, nullptr);
        throw;
    }
    VK_CHECK(vkBindBufferMemory(context.device, result.buffer, result.memory, 0));
    if (use != MemoryUse::DeviceLocal) VK_CHECK(vkMapMemory(context.device, result.memory, 0, VK_WHOLE_SIZE, 0, &result.mapped));
    context.setDebugName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(result.buffer), what.c_str());
    return result;
}

void destroyBuffer(const VulkanContext& context, Buffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(context.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(context.device, buffer.memory, nullptr);
    buffer = Buffer{};
}

Buffer createBufferWithData(const VulkanContext& context, std::span<const std::byte> data, VkBufferUsageFlags usage,
                            const std::string& what) {
    Buffer staging = createBuffer(context, data.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostUpload,
                                  what + " (staging)");
    std::memcpy(staging.mapped, data.data(), data.size());
    Buffer result;
    try {
        result = createBuffer(context, data.size(), usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal, what);
    } catch (...) {
        destroyBuffer(context, staging);
        throw;
    }
    // Deferred on a borrowed device: the copy names the handles, the staging buffer waits for it.
    const VkBuffer source = staging.buffer, destination = result.buffer;
    const VkBufferCopy region{0, 0, data.size()};
    try {
        runOneShot(
            context, [=](VkCommandBuffer cmd) { vkCmdCopyBuffer(cmd, source, destination, 1, &region); },
            [&context, staging]() mutable { destroyBuffer(context, staging); });
    } catch (...) {
        destroyBuffer(context, result);
        throw;
    }
    return result;
}

}  // namespace gpu
