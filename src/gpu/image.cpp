#include "gpu/image.h"

#include "gpu/buffer.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace gpu {

Image createImage2D(const VulkanContext& context, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                    const std::string& what) {
    Image result;
    result.format = format;
    result.extent = extent;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(context.device, &info, nullptr, &result.image));
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(context.device, result.image, &requirements);
    result.bytes = requirements.size;
    try {
        result.memory = allocateMemory(context, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
        VK_CHECK(vkBindImageMemory(context.device, result.image, result.memory, 0));
        const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D24_UNORM_S8_UINT;
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = result.image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {static_cast<VkImageAspectFlags>(depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                                     0, 1, 0, 1};
        VK_CHECK(vkCreateImageView(context.device, &viewInfo, nullptr, &result.view));
    } catch (...) {
        destroyImage(context, result);
        throw;
    }
    context.setDebugName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(result.image), what.c_str());
    return result;
}

void destroyImage(const VulkanContext& context, Image& image) {
    if (image.view) vkDestroyImageView(context.device, image.view, nullptr);
    if (image.image) vkDestroyImage(context.device, image.image, nullptr);
    if (image.memory) vkFreeMemory(context.device, image.memory, nullptr);
    image = Image{};
}

}  // namespace gpu
