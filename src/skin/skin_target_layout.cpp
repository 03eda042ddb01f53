#include "skin/skin_target_layout.h"

#include <algorithm>

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace skin {

VkExtent2D SkinTargetLayout::tileExtent(std::uint32_t tile) const {
    return {width, std::min(rowsPerTile, totalRows - firstRow(tile))};
}

SkinTargetLayout planSkinTargets(std::uint64_t capacity, std::uint32_t maxDimension) {
    if (maxDimension == 0) throw gpu::Error("skinning target: the image size limit must be positive");
    SkinTargetLayout layout;
    layout.capacity = std::max<std::uint64_t>(capacity, 1);
    layout.width = std::min(kPreferredTargetWidth, maxDimension);
    layout.totalRows = static_cast<std::uint32_t>((layout.capacity + layout.width - 1) / layout.width);
    layout.rowsPerTile = std::min(layout.totalRows, maxDimension);
    layout.tileCount = (layout.totalRows + layout.rowsPerTile - 1) / layout.rowsPerTile;
    return layout;
}

std::uint32_t maxSkinTargetDimension(const gpu::VulkanContext& context, std::uint32_t requested) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    const std::uint32_t device =
        std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxFramebufferHeight});
    return requested ? std::min(requested, device) : device;
}

}  // namespace skin
