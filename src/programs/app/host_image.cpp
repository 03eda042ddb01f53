#include "app/host_image.h"

#include "app/error.h"
#include "app/host_device.h"
#include "app/number_text.h"

namespace app {
namespace {

VkDeviceMemory allocate(const HostDevice& device, const VkMemoryRequirements& requirements,
                        VkMemoryPropertyFlags flags, const std::string& what) {
    const int type = device.memoryType(requirements.memoryTypeBits, flags);
    if (type < 0) throw Error("no suitable memory type for " + what);
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = static_cast<std::uint32_t>(type);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult result = vkAllocateMemory(device.device, &info, nullptr, &memory);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw Error(std::string(resultName(result)) + " allocating " + formatBytes(requirements.size) + " for " + what +
                    " (try a smaller --size)");
    check(result, "vkAllocateMemory");
    return memory;
}

bool isDepth(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D24_UNORM_S8_UINT ||
           format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

}  // namespace

HostImage createImage(const HostDevice& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                      const std::string& what, VkSampleCountFlagBits samples, VkFormat viewFormat) {
    const bool otherView = viewFormat != VK_FORMAT_UNDEFINED && viewFormat != format;
    HostImage image;
    image.extent = extent;
    image.format = format;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (otherView) info.flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT | VK_IMAGE_CREATE_EXTENDED_USAGE_BIT;
    try {
        check(vkCreateImage(device.device, &info, nullptr, &image.image), "vkCreateImage");
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device.device, image.image, &requirements);
        image.memory = allocate(device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, what);
        image.bytes = requirements.size;
        check(vkBindImageMemory(device.device, image.image, image.memory, 0), "vkBindImageMemory");
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image.image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = otherView ? viewFormat : format;
        viewInfo.subresourceRange = {isDepth(format) ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)
                                                     : VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT),
                                     0, 1, 0, 1};
        check(vkCreateImageView(device.device, &viewInfo, nullptr, &image.view), "vkCreateImageView");
    } catch (...) {
        destroyImage(device, image);
        throw;
    }
    return image;
}

void destroyImage(const HostDevice& device, HostImage& image) {
    if (image.view) vkDestroyImageView(device.device, image.view, nullptr);
    if (image.image) vkDestroyImage(device.device, image.image, nullptr);
    if (image.memory) vkFreeMemory(device.device, image.memory, nullptr);
    image = {};
}

void copiedForHost(VkCommandBuffer cmd, const ReadbackBuffer& buffer) {
    VkBufferMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = buffer.buffer;
    toHost.size = VK_WHOLE_SIZE;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.bufferMemoryBarrierCount = 1;
    dependency.pBufferMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

ReadbackBuffer createReadbackBuffer(const HostDevice& device, VkDeviceSize size, const std::string& what) {
    ReadbackBuffer buffer;
    buffer.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    try {
        check(vkCreateBuffer(device.device, &info, nullptr, &buffer.buffer), "vkCreateBuffer");
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(device.device, buffer.buffer, &requirements);
        buffer.memory = allocate(device, requirements,
                                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, what);
        check(vkBindBufferMemory(device.device, buffer.buffer, buffer.memory, 0), "vkBindBufferMemory");
        check(vkMapMemory(device.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &buffer.mapped), "vkMapMemory");
    } catch (...) {
        destroyReadbackBuffer(device, buffer);
        throw;
    }
    return buffer;
}

void destroyReadbackBuffer(const HostDevice& device, ReadbackBuffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(device.device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(device.device, buffer.memory, nullptr);  // unmaps it
    buffer = {};
}

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
                     VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                     VkImageLayout oldLayout, VkImageLayout newLayout) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = oldLayout;
    barrier.newLayout = newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace app
