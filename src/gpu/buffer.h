#pragma once
// A VkBuffer with its own memory allocation; host-visible buffers stay mapped.
#include <cstdint>
#include <span>
#include <string>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

enum class MemoryUse {
    DeviceLocal,  // GPU-only data, filled by copies or shaders
    HostUpload,   // written by the CPU every frame, read by the GPU
    HostReadback, // written by the GPU, read by the CPU
};

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // non-null for host-visible buffers
};

// Creates a buffer of `size` bytes; `what` names it in errors ("out of device memory allocating
// 1.2 GiB for skinned vertices") and in validation messages.
Buffer createBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const std::string& what);
void destroyBuffer(const VulkanContext& context, Buffer& buffer);

// Creates a device-local buffer and fills it through a staging copy that completes before returning.
Buffer createBufferWithData(const VulkanContext& context, std::span<const std::byte> data, VkBufferUsageFlags usage,
                            const std::string& what);

// Allocates memory of a type allowed by `typeBits` with `properties`; throws a clear Error on failure.
VkDeviceMemory allocateMemory(const VulkanContext& context, const VkMemoryRequirements& requirements,
                              VkMemoryPropertyFlags properties, const std::string& what);

// "1.5 GiB", "12.0 MiB": sizes in messages.
std::string formatBytes(std::uint64_t bytes);

}  // namespace gpu
