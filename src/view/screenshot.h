#pragma once
// A screenshot of the window: the swapchain image, scene and panel as presented, copied to host
// memory by the frame's own commands and turned into RGBA8 for render::writePng.
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "render/png_writer.h"
#include "view/present_commands.h"

namespace gpu { class VulkanContext; }

namespace view {

class Screenshot {
public:
    Screenshot(const gpu::VulkanContext& context, VkExtent2D extent, VkFormat format);
    ~Screenshot();
    Screenshot(const Screenshot&) = delete;
    Screenshot& operator=(const Screenshot&) = delete;

    // Records the copy of the finished image (it stays in TRANSFER_SRC_OPTIMAL until presented).
    void record(VkCommandBuffer cmd, SwapchainImage& image);
    // The pixels, once the frame's commands have completed.
    render::Rgba8Image pixels() const;

private:
    const gpu::VulkanContext& context_;
    VkExtent2D extent_;
    VkFormat format_;
    gpu::Buffer buffer_;
};

}  // namespace view
