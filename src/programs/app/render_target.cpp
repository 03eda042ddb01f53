#include "app/render_target.h"

#include <cstring>

#include "app/error.h"
#include "app/host_device.h"

namespace app {

RenderTarget::RenderTarget(const HostDevice& device, VkExtent2D extent, const crowdgpu::TargetFormat& format,
                           bool edgeFilter)
    : device_(device), samples_(format.samples) {
    if (edgeFilter && format.color != VK_FORMAT_R8G8B8A8_SRGB && format.color != VK_FORMAT_R8G8B8A8_UNORM)
        throw Error("the edge filter writes R8G8B8A8 pictures only (the target's colour format is " +
                    std::to_string(format.color) + ")");
    try {
        if (edgeFilter) {
            // The filter writes the picture through a UNORM view (sRGB is no storage format).
            color_ = createImage(device, extent, format.color, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 "scene colour", VK_SAMPLE_COUNT_1_BIT, VK_FORMAT_R8G8B8A8_UNORM);
            drawn_ = createImage(device, extent, format.color,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "scene colour drawn");
        } else {
            color_ = createImage(device, extent, format.color,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "scene colour");
        }
        // The samples live only within the pass (resolved at its end): transient, never copied.
        if (samples_ != VK_SAMPLE_COUNT_1_BIT)
            multisampled_ = createImage(device, extent, format.color,
                                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                        "scene colour samples", samples_);
        depth_ = createImage(device, extent, format.depth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "scene depth",
                             samples_);
    } catch (...) {
        release();
        throw;
    }
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
