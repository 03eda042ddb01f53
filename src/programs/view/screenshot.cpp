#include "view/screenshot.h"

#include <algorithm>
#include <cstring>

#include "app/host_device.h"

namespace view {

Screenshot::Screenshot(const app::HostDevice& context, VkExtent2D extent, VkFormat format)
    : context_(context),
      extent_(extent),
      format_(format),
      buffer_(app::createReadbackBuffer(context, static_cast<VkDeviceSize>(extent.width) * extent.height * 4,
                                        "screenshot")) {}

Screenshot::~Screenshot() { app::destroyReadbackBuffer(context_, buffer_); }

void Screenshot::record(VkCommandBuffer cmd, SwapchainImage& image) {
    transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_.buffer, 1, &region);
    app::copiedForHost(cmd, buffer_);
}

app::Rgba8Image Screenshot::pixels() const {
    const std::size_t size = static_cast<std::size_t>(extent_.width) * extent_.height * 4;
    app::Rgba8Image image{extent_.width, extent_.height, std::vector<std::uint8_t>(size)};
    std::memcpy(image.pixels.data(), buffer_.mapped, size);
    const bool bgra = format_ == VK_FORMAT_B8G8R8A8_SRGB || format_ == VK_FORMAT_B8G8R8A8_UNORM;
    for (std::size_t p = 0; p < size; p += 4) {
        if (bgra) std::swap(image.pixels[p], image.pixels[p + 2]);
        // The window is opaque (composite alpha OPAQUE): what it shows has no transparency.
        image.pixels[p + 3] = 255;
    }
    return image;
}

}  // namespace view
