#pragma once
// The commands that put a rendered scene on the window, recorded after the scene in the same
// command buffer: a blit of the scene image into the acquired swapchain image, then the layout
// changes the UI pass, a screenshot copy and presentation need. Each step records what it did to
// the image so the next barrier waits for exactly that.
#include <vulkan/vulkan.h>

namespace view {

// A pipeline stage and the access it makes: one side of a barrier.
struct Access {
    VkPipelineStageFlags2 stage;
    VkAccessFlags2 access;
};

struct SwapchainImage {
    VkImage image = VK_NULL_HANDLE;
    VkExtent2D extent{0, 0};
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    // The last work on the image in this command buffer; before any, the acquire semaphore's wait
    // (the renderer waits on it at all stages, so any stage here continues that dependency).
    Access last{VK_PIPELINE_STAGE_2_BLIT_BIT, 0};
};

// A barrier from the image's last work to `next`, in layout `layout`.
void transition(VkCommandBuffer cmd, SwapchainImage& target, VkImageLayout layout, Access next);

// Copies the scene (TRANSFER_SRC_OPTIMAL, as the renderer leaves it) into the swapchain image,
// converting RGBA to the swapchain's channel order. The old contents are discarded.
void blitScene(VkCommandBuffer cmd, VkImage scene, VkExtent2D sceneExtent, SwapchainImage& target);

// Leaves the image ready for the UI pass (colour attachment, contents kept).
void prepareForUi(VkCommandBuffer cmd, SwapchainImage& target);

// Hands the image to the presentation engine; the frame's signal semaphore orders the rest.
void prepareForPresent(VkCommandBuffer cmd, SwapchainImage& target);

}  // namespace view
