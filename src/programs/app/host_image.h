#pragma once
// The few Vulkan resources the programs make themselves (the library makes its own): a 2D image with
// its memory and view, a host-readable buffer, and an image layout transition.
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

struct HostImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkDeviceSize bytes = 0;
};
// A device-local 2D image of `samples` per pixel; a depth format gets a depth view. Throws Error
// naming `what` when the device has no memory for it. `viewFormat`, when given, is the view's format
// instead of the image's (a UNORM view of an sRGB image, for storage: the image is made mutable, its
// usage checked against the view's format).
HostImage createImage(const HostDevice& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                      const std::string& what, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT,
                      VkFormat viewFormat = VK_FORMAT_UNDEFINED);
void destroyImage(const HostDevice& device, HostImage& image);

struct ReadbackBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkDeviceSize size = 0;
};
// A host-visible, mapped buffer the GPU copies into (transfer destination).
ReadbackBuffer createReadbackBuffer(const HostDevice& device, VkDeviceSize size, const std::string& what);
void destroyReadbackBuffer(const HostDevice& device, ReadbackBuffer& buffer);
// After a copy into the buffer: the host may read it once the command buffer's fence has signalled.
void copiedForHost(VkCommandBuffer cmd, const ReadbackBuffer& buffer);

// One synchronization2 image barrier over the whole image.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
                     VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                     VkImageLayout oldLayout, VkImageLayout newLayout);

}  // namespace app
