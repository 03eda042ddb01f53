#pragma once
// The window's swapchain: sRGB images the scene is blitted into (and read back from for
// screenshots), the present mode vsync asks for, and the semaphores of acquire and present.
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace app { class HostDevice; }

namespace view {

class Swapchain {
public:
    // Takes ownership of `surface`. `framesInFlight` is the renderer's: it sizes the acquire semaphores.
    Swapchain(const app::HostDevice& context, VkSurfaceKHR surface, VkExtent2D size, bool vsync,
              std::uint32_t framesInFlight);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Replaces the swapchain with one of the surface's current size (or `size` where the surface
    // leaves it to us), within largestExtent(); waits for the device first. Returns false, changing
    // nothing, while the surface has no area (minimized: a swapchain cannot have a zero extent) or asks
    // for images larger than largestExtent() (the window must shrink first).
    bool recreate(VkExtent2D size);

    struct Frame {
        std::uint32_t imageIndex;
        VkImage image;
        VkSemaphore acquired;  // signalled when the image may be written
        VkSemaphore rendered;  // to be signalled by the frame's commands; present waits on it
    };
    // The next image, or nothing when the swapchain no longer matches the surface (recreate, retry).
    std::optional<Frame> acquire();
    // Presents the frame; false when the swapchain should be recreated before the next frame.
    bool present(const Frame& frame);

    VkFormat format() const { return format_; }
    // The images' size: the window's, within the surface's extent limits and largestExtent().
    VkExtent2D extent() const { return extent_; }
    // The largest images the device can present (its image, framebuffer and viewport limits, which
    // surfaces may not reflect: lavapipe's X11 surface accepts any window). The window must not grow
    // beyond it.
    VkExtent2D largestExtent() const { return largest_; }
    // The window size the swapchain was made for; it needs remaking when the window's differs (its
    // extent may, when the window is larger than the surface allows).
    VkExtent2D windowSize() const { return windowSize_; }
    VkPresentModeKHR presentMode() const { return presentMode_; }
    std::uint32_t minImageCount() const { return minImageCount_; }
    const std::vector<VkImageView>& views() const { return views_; }
    std::uint32_t imageCount() const { return static_cast<std::uint32_t>(images_.size()); }
    // Screenshots read the image back; false on surfaces that do not allow transfers out.
    bool canReadBack() const { return canReadBack_; }

private:
    void create(VkExtent2D size, VkSwapchainKHR old);
    void destroyViews();
    void release();

    const app::HostDevice& context_;
    VkSurfaceKHR surface_;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkExtent2D extent_{0, 0};
    VkExtent2D windowSize_{0, 0};
    VkExtent2D largest_{0, 0};
    std::uint32_t minImageCount_ = 0;
    bool canReadBack_ = false;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkSemaphore> acquired_;  // a ring, see acquire()
    std::vector<VkSemaphore> rendered_;  // one per image
    std::uint32_t nextAcquire_ = 0;
};

}  // namespace view
