#include "app/render_target.h"

#include <algorithm>
#include <cstring>

#include "app/error.h"
#include "app/host_device.h"

namespace app {

std::vector<RenderTarget::Image> RenderTarget::images(const crowdgpu::TargetFormat& format, bool edgeFilter) {
    std::vector<Image> list;
    if (edgeFilter) {
        // The filter writes the picture through a UNORM view (sRGB is no storage format).
        list.push_back({&RenderTarget::color_, format.color, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                        VK_SAMPLE_COUNT_1_BIT, VK_FORMAT_R8G8B8A8_UNORM, "scene colour"});
        list.push_back({&RenderTarget::drawn_, format.color,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_SAMPLE_COUNT_1_BIT,
                        VK_FORMAT_UNDEFINED, "scene colour drawn"});
    } else {
        list.push_back({&RenderTarget::color_, format.color,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_SAMPLE_COUNT_1_BIT,
                        VK_FORMAT_UNDEFINED, "scene colour"});
    }
    // The samples live only within the pass (resolved at its end): transient, never copied.
    if (format.samples != VK_SAMPLE_COUNT_1_BIT)
        list.push_back({&RenderTarget::multisampled_, format.color,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT, format.samples,
                        VK_FORMAT_UNDEFINED, "scene colour samples"});
    list.push_back({&RenderTarget::depth_, format.depth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, format.samples,
                    VK_FORMAT_UNDEFINED, "scene depth"});
    return list;
}

RenderTarget::RenderTarget(const HostDevice& device, VkExtent2D extent, const crowdgpu::TargetFormat& format,
                           bool edgeFilter)
    : device_(device), samples_(format.samples) {
    if (edgeFilter && format.color != VK_FORMAT_R8G8B8A8_SRGB && format.color != VK_FORMAT_R8G8B8A8_UNORM)
        throw Error("the edge filter writes R8G8B8A8 pictures only (the target's colour format is " +
                    std::to_string(format.color) + ")");
    try {
        for (const Image& image : images(format, edgeFilter))
            this->*image.member =
                createImage(device, extent, image.format, image.usage, image.what, image.samples, image.viewFormat);
    } catch (...) {
        release();
        throw;
    }
}

std::string RenderTarget::limitProblem(const HostDevice& device, VkExtent2D extent, const crowdgpu::TargetFormat& format,
                                       bool edgeFilter) {
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &maintenance3};
    vkGetPhysicalDeviceProperties2(device.physicalDevice, &properties);
    const std::string size = std::to_string(extent.width) + "x" + std::to_string(extent.height);
    for (const Image& image : images(format, edgeFilter)) {
        VkImageFormatProperties limits{};
        const VkImageCreateFlags flags = image.viewFormat != VK_FORMAT_UNDEFINED
                                             ? VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT | VK_IMAGE_CREATE_EXTENDED_USAGE_BIT
                                             : 0u;
        if (vkGetPhysicalDeviceImageFormatProperties(device.physicalDevice, image.format, VK_IMAGE_TYPE_2D,
                                                     VK_IMAGE_TILING_OPTIMAL, image.usage, flags,
                                                     &limits) != VK_SUCCESS ||
            !(limits.sampleCounts & image.samples))
            return std::string(image.what) + ": the device cannot make this image";
        if (extent.width > limits.maxExtent.width || extent.height > limits.maxExtent.height)
            return std::string(image.what) + ": " + size + " is past the device's largest image, " +
                   std::to_string(limits.maxExtent.width) + "x" + std::to_string(limits.maxExtent.height);
        // Every target format is 4 bytes a texel (the readback copies 4 bytes a pixel; D32 depth).
        const std::uint64_t bytes = std::uint64_t{extent.width} * extent.height * 4u * image.samples;
        const std::uint64_t largest = std::min<std::uint64_t>(limits.maxResourceSize, maintenance3.maxMemoryAllocationSize);
        if (bytes > largest)
            return std::string(image.what) + ": " + size + " at " + std::to_string(image.samples) +
                   " sample(s) a pixel is " + std::to_string(bytes >> 20) + " MiB, past the device's largest image of " +
                   std::to_string(largest >> 20) + " MiB";
    }
    return {};
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
    destroyImage(device_, depth_);
    destroyImage(device_, multisampled_);
    destroyImage(device_, drawn_);
    destroyImage(device_, color_);
}

void RenderTarget::beginRendering(VkCommandBuffer cmd, const float clearColor[4], ColourLoad load) {
    // The previous frame's writes (and readback copy, or filter's reads) must finish before this frame
    // draws.
    const HostImage& picture = edgeFiltered() ? drawn_ : color_;
    transitionImage(cmd, picture.image, VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT |
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    0,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
                    VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    const bool multisampled = multisampled_.image != VK_NULL_HANDLE;
    if (multisampled)  // the previous frame's samples were written in the pass (and discarded at its end)
        transitionImage(cmd, multisampled_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
                        VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    constexpr VkPipelineStageFlags2 depthTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    transitionImage(cmd, depth_.image, VK_IMAGE_ASPECT_DEPTH_BIT, depthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                    VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);

    VkRenderingAttachmentInfo colorAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    colorAttachment.imageView = multisampled ? multisampled_.view : picture.view;
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = load == ColourLoad::Clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (multisampled) {
        // The average of a pixel's samples is its picture; the samples themselves are not kept.
        colorAttachment.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        colorAttachment.resolveImageView = picture.view;
        colorAttachment.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    }
    std::memcpy(colorAttachment.clearValue.color.float32, clearColor, 4 * sizeof(float));
    VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depth_.view;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, color_.extent};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &colorAttachment;
    info.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(cmd, &info);
}

void RenderTarget::endRendering(VkCommandBuffer cmd) {
    vkCmdEndRendering(cmd);
    if (edgeFiltered()) {
        // The filter samples what was drawn and writes the picture (once the previous frame's copy of
        // it is done).
        transitionImage(cmd, drawn_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        transitionImage(cmd, color_.image, VK_IMAGE_ASPECT_COLOR_BIT,
                        VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                        VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        return;
    }
    // Any transfer next: the readback copies, the viewer blits to its swapchain. The resolve, too, is
    // a colour attachment write.
    transitionImage(cmd, color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

void RenderTarget::endFiltering(VkCommandBuffer cmd) {
    transitionImage(cmd, color_.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                    VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

Rgba8Image RenderTarget::readback() {
    const VkExtent2D extent = color_.extent;
    const VkDeviceSize size = static_cast<VkDeviceSize>(extent.width) * extent.height * 4;
    ReadbackBuffer staging = createReadbackBuffer(device_, size, "scene readback");
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &region);
    });
    Rgba8Image image{extent.width, extent.height, std::vector<std::uint8_t>(size)};
    std::memcpy(image.pixels.data(), staging.mapped, size);
    destroyReadbackBuffer(device_, staging);
    return image;
}

std::uint64_t renderTargetBytes(VkExtent2D extent, VkSampleCountFlagBits samples, bool edgeFilter) {
    // 4 bytes of colour and 4 of depth per sample, the resolved colour beside the samples, and the
    // filter's picture beside what it filters.
    const std::uint64_t pixels = static_cast<std::uint64_t>(extent.width) * extent.height;
    return pixels * (8 * static_cast<std::uint64_t>(samples) + (samples == VK_SAMPLE_COUNT_1_BIT ? 0 : 4) +
                     (edgeFilter ? 4 : 0));
}

}  // namespace app
