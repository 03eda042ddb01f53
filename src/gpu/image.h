#pragma once
// A 2D VkImage with its own memory and one view.
#include <string>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{0, 0};
    VkDeviceSize bytes = 0;  // size of its memory allocation
};

Image createImage2D(const VulkanContext& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                    const std::string& what);
void destroyImage(const VulkanContext& context, Image& image);

}  // namespace gpu
