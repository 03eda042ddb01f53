#include "view/swapchain.h"

#include <algorithm>
#include <cstdio>

#include "app/host_device.h"
#include "app/error.h"

namespace view {
namespace {

template <typename T, typename Query>
std::vector<T> enumerate(Query query) {
    std::uint32_t count = 0;
    CHECK_VK(query(&count, nullptr));
    std::vector<T> items(count);
    CHECK_VK(query(&count, items.data()));
    items.resize(count);
    return items;
}

VkSurfaceFormatKHR chooseFormat(const app::HostDevice& context, VkSurfaceKHR surface) {
    const auto formats = enumerate<VkSurfaceFormatKHR>([&](std::uint32_t* n, VkSurfaceFormatKHR* f) {
        return vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice, surface, n, f);
    });
    // The scene image is sRGB. A blit between two sRGB images decodes and re-encodes, so the window
    // shows the very bytes crowd-render writes; the channel order is the blit's business.
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(context.physicalDevice, wanted, &properties);
        if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT)) continue;
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    }
    throw app::Error("the window's surface offers neither B8G8R8A8_SRGB nor R8G8B8A8_SRGB on " +
                     context.description.name + "; crowd-render renders without a window");
}

VkPresentModeKHR choosePresentMode(const app::HostDevice& context, VkSurfaceKHR surface, bool vsync) {
    if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // the one mode every surface has
    const auto modes = enumerate<VkPresentModeKHR>([&](std::uint32_t* n, VkPresentModeKHR* m) {
        return vkGetPhysicalDeviceSurfacePresentModesKHR(context.physicalDevice, surface, n, m);
    });
    // MAILBOX never waits for vblank and never tears; IMMEDIATE never waits but may tear.
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
    std::fprintf(stderr, "crowd-view: --vsync off: the surface has only FIFO; frames stay synchronized "
                         "to the display\n");
    return VK_PRESENT_MODE_FIFO_KHR;
}

// The largest image of `format` and `usage` the device can create, render into (framebuffer and
// viewport) and the renderer can match with its own target. Surfaces may allow more: lavapipe's X11
// surface reports any window size as its maximum, while its images stop at 16384.
VkExtent2D deviceMaxExtent(const app::HostDevice& context, VkFormat format, VkImageUsageFlags usage) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    VkImageFormatProperties image{};
    CHECK_VK(vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice, format, VK_IMAGE_TYPE_2D,
                                                      VK_IMAGE_TILING_OPTIMAL, usage, 0, &image));
    return {std::min({image.maxExtent.width, limits.maxImageDimension2D, limits.maxFramebufferWidth,
                      limits.maxViewportDimensions[0]}),
            std::min({image.maxExtent.height, limits.maxImageDimension2D, limits.maxFramebufferHeight,
                      limits.maxViewportDimensions[1]})};
}

// The window's size (currentExtent; 0xFFFFFFFF where the surface takes its size from the swapchain, as
// on Wayland) clamped to the surface's minimum and maximum extent and the device's maximum. Zero when
// there can be no swapchain: the window is minimized, or the surface insists on a size beyond what the
// device can make (X11 surfaces ask for exactly the window's size, and a window can be larger than any
// image).
VkExtent2D extentFor(const VkSurfaceCapabilitiesKHR& caps, VkExtent2D size, VkExtent2D deviceMax) {
    const VkExtent2D window = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : size;
    const VkExtent2D max{std::min(caps.maxImageExtent.width, deviceMax.width),
                         std::min(caps.maxImageExtent.height, deviceMax.height)};
    if (window.width == 0 || window.height == 0) return {0, 0};
    if (caps.minImageExtent.width > max.width || caps.minImageExtent.height > max.height) return {0, 0};
    return {std::clamp(window.width, caps.minImageExtent.width, max.width),
            std::clamp(window.height, caps.minImageExtent.height, max.height)};
}

VkImageUsageFlags imageUsage(bool readBack) {
    return VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
           (readBack ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT} : 0u);
}

VkSemaphore createSemaphore(const app::HostDevice& context) {
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    CHECK_VK(vkCreateSemaphore(context.device, &info, nullptr, &semaphore));
    return semaphore;
}

}  // namespace

Swapchain::Swapchain(const app::HostDevice& context, VkSurfaceKHR surface, VkExtent2D size, bool vsync,
                     std::uint32_t framesInFlight)
    : context_(context), surface_(surface) {
    try {
        VkBool32 supported = VK_FALSE;
        CHECK_VK(
            vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice, context.queueFamily, surface, &supported));
        if (!supported)
            throw app::Error("device " + context.description.name + " cannot present to this window (try --device)");
        const VkSurfaceFormatKHR format = chooseFormat(context, surface);
        format_ = format.format;
        colorSpace_ = format.colorSpace;
        presentMode_ = choosePresentMode(context, surface, vsync);
        // vkAcquireNextImageKHR for frame N comes before the renderer waits for the fence of frame
        // N - framesInFlight, so that frame's wait on its acquire semaphore may still be pending. One
        // more semaphore in the ring makes frame N reuse the one of frame N - framesInFlight - 1,
        // whose fence the renderer waited for while starting the previous frame.
        for (std::uint32_t i = 0; i < framesInFlight + 1; ++i) acquired_.push_back(createSemaphore(context));
        create(size, VK_NULL_HANDLE);
    } catch (...) {
        release();
        throw;
    }
}

Swapchain::~Swapchain() { release(); }

void Swapchain::release() {
    vkDeviceWaitIdle(context_.device);
    for (VkSemaphore s : acquired_) vkDestroySemaphore(context_.device, s, nullptr);
    for (VkSemaphore s : rendered_) vkDestroySemaphore(context_.device, s, nullptr);
    acquired_.clear();
    rendered_.clear();
    destroyViews();
    if (swapchain_) vkDestroySwapchainKHR(context_.device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    if (surface_) vkDestroySurfaceKHR(context_.instance, surface_, nullptr);
    surface_ = VK_NULL_HANDLE;
}

bool Swapchain::recreate(VkExtent2D size) {
    VkSurfaceCapabilitiesKHR caps;
    CHECK_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice, surface_, &caps));
    largest_ = deviceMaxExtent(context_, format_, imageUsage(canReadBack_));
    const VkExtent2D extent = extentFor(caps, size, largest_);
    if (extent.width == 0 || extent.height == 0) return false;  // minimized or too large since the caller looked
    CHECK_VK(vkDeviceWaitIdle(context_.device));
    destroyViews();
    VkSwapchainKHR old = swapchain_;
    swapchain_ = VK_NULL_HANDLE;
    try {
        create(size, old);
    } catch (...) {
        vkDestroySwapchainKHR(context_.device, old, nullptr);
        throw;
    }
    vkDestroySwapchainKHR(context_.device, old, nullptr);
    return true;
}

void Swapchain::create(VkExtent2D size, VkSwapchainKHR old) {
    VkSurfaceCapabilitiesKHR caps;
    CHECK_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice, surface_, &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw app::Error("the window's swapchain images cannot be blitted to on " + context_.description.name);
    canReadBack_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    windowSize_ = size;
    largest_ = deviceMaxExtent(context_, format_, imageUsage(canReadBack_));
    extent_ = extentFor(caps, size, largest_);
    if (extent_.width == 0 || extent_.height == 0)
        throw app::Error("cannot draw into a " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                         " window on " + context_.description.name + " (minimized, or larger than its largest image, " +
                         std::to_string(largest_.width) + "x" + std::to_string(largest_.height) + ")");
    minImageCount_ = caps.minImageCount + 1;  // one more than the minimum: never wait for the display to let one go
    if (caps.maxImageCount > 0) minImageCount_ = std::min(minImageCount_, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = minImageCount_;
    info.imageFormat = format_;
    info.imageColorSpace = colorSpace_;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = imageUsage(canReadBack_);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                         -caps.supportedCompositeAlpha);
    info.presentMode = presentMode_;
    // Not clipped: a screenshot must hold the whole image even where another window covers ours.
    info.clipped = VK_FALSE;
    info.oldSwapchain = old;
    CHECK_VK(vkCreateSwapchainKHR(context_.device, &info, nullptr, &swapchain_));

    images_ = enumerate<VkImage>([&](std::uint32_t* n, VkImage* i) {
        return vkGetSwapchainImagesKHR(context_.device, swapchain_, n, i);
    });
    for (VkImage image : images_) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        CHECK_VK(vkCreateImageView(context_.device, &view, nullptr, &views_.emplace_back()));
    }
    // Kept across recreations (only ever added to): a present may still wait on one after the device
    // is idle, and a semaphore is only safe to destroy when the presentation engine is done with it.
    while (rendered_.size() < images_.size()) rendered_.push_back(createSemaphore(context_));
}

void Swapchain::destroyViews() {
    for (VkImageView view : views_) vkDestroyImageView(context_.device, view, nullptr);
    views_.clear();
}

std::optional<Swapchain::Frame> Swapchain::acquire() {
    VkSemaphore semaphore = acquired_[nextAcquire_];
    std::uint32_t index = 0;
    const VkResult result =
        vkAcquireNextImageKHR(context_.device, swapchain_, UINT64_MAX, semaphore, VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;  // nothing signalled: the semaphore stays free
    if (result != VK_SUBOPTIMAL_KHR) CHECK_VK(result);            // suboptimal still acquired an image
    nextAcquire_ = (nextAcquire_ + 1) % static_cast<std::uint32_t>(acquired_.size());
    return Frame{index, images_[index], semaphore, rendered_[index]};
}

bool Swapchain::present(const Frame& frame) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &frame.rendered;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &frame.imageIndex;
    const VkResult result = vkQueuePresentKHR(context_.queue, &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
    CHECK_VK(result);
    return true;
}

}  // namespace view
