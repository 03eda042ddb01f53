#pragma once
// The programs' offscreen image the scene is drawn into (sRGB colour + depth), and its readback.
#include <vulkan/vulkan.h>

#include "app/host_image.h"
#include "app/png_writer.h"


namespace app {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

class RenderTarget {
public:
    // 4-byte colour formats only (the readback copies 4 bytes a pixel).
    RenderTarget(const HostDevice& device, VkExtent2D extent, VkFormat color = kColorFormat,
                 VkFormat depth = kDepthFormat);
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    VkExtent2D extent() const { return color_.extent; }
    VkImage colorImage() const { return color_.image; }
    // Transitions the images and begins dynamic rendering, clearing to `clearColor` (linear).
    void beginRendering(VkCommandBuffer cmd, const float clearColor[4]);
    // Ends rendering and leaves the colour image ready to be copied out.
    void endRendering(VkCommandBuffer cmd);
    // Copies the last rendered frame to the host (waits for the GPU).
    Rgba8Image readback();
    VkDeviceSize bytes() const { return color_.bytes + depth_.bytes; }

private:
    const HostDevice& device_;
    HostImage color_;
    HostImage depth_;
};

}  // namespace app
