#include "view/present_commands.h"

#include "app/host_image.h"

namespace view {

void transition(VkCommandBuffer cmd, SwapchainImage& target, VkImageLayout layout, Access next) {
    app::transitionImage(cmd, target.image, VK_IMAGE_ASPECT_COLOR_BIT, target.last.stage, target.last.access, next.stage,
                         next.access, target.layout, layout);
    target.layout = layout;
    target.last = next;
}

void blitScene(VkCommandBuffer cmd, VkImage scene, VkExtent2D sceneExtent, SwapchainImage& target) {
    // From UNDEFINED: the previous frame's contents of this image are not needed.
    target.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    transition(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               {VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {static_cast<int32_t>(sceneExtent.width), static_cast<int32_t>(sceneExtent.height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {static_cast<int32_t>(target.extent.width), static_cast<int32_t>(target.extent.height), 1};
    // The renderer is resized with the swapchain, so the blit is mostly 1:1 and nearest sampling copies
    // each pixel; a blit rather than a copy because the channel order may differ (BGRA windows). A
    // window past the device's limits is drawn smaller and scaled up, filtered (linear filtering of the
    // scene's R8G8B8A8_SRGB is a format feature every Vulkan device has).
    const bool oneToOne = sceneExtent.width == target.extent.width && sceneExtent.height == target.extent.height;
    vkCmdBlitImage(cmd, scene, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &region, oneToOne ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
}

void prepareForUi(VkCommandBuffer cmd, SwapchainImage& target) {
    // The UI pass loads the blitted scene and blends onto it.
    transition(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
}

void prepareForPresent(VkCommandBuffer cmd, SwapchainImage& target) {
    transition(cmd, target, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, {VK_PIPELINE_STAGE_2_NONE, 0});
}

}  // namespace view
