#pragma once
// A screenshot of the window: the swapchain image, scene and panel as presented, copied to host
// memory by the frame's own commands and turned into RGBA8 for app::writePng.
#include <vulkan/vulkan.h>

#include "app/host_image.h"
#include "app/png_writer.h"
#include "view/present_commands.h"

namespace app { class HostDevice; }

namespace view {

class Screenshot {
public:
    Screenshot(const app::HostDevice& context, VkExtent2D extent, VkFormat format);
    ~Screenshot();
    Screenshot(const Screenshot&) = delete;
    Screenshot& operator=(const Screenshot&) = delete;

    // Records the copy of the finished image (it stays in TRANSFER_SRC_OPTIMAL until presented).
    void record(VkCommandBuffer cmd, SwapchainImage& image);
    // The pixels, once the frame's commands have completed.
    app::Rgba8Image pixels() const;

private:
    const app::HostDevice& context_;
    VkExtent2D extent_;
    VkFormat format_;
    app::ReadbackBuffer buffer_;
};

}  // namespace view
