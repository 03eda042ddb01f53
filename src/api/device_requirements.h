#pragma once
// Checks of what a host lends: the device's features as it enabled them, and its target formats.
#include "crowdgpu/renderer.hpp"
#include "gpu/vulkan_context.h"

namespace crowdgpu::detail {

// Throws Error (InvalidArgument or Unsupported) naming what is missing; else the handles to wrap.
gpu::BorrowedHandles checkBorrowedDevice(const Device& device);
void checkTargetFormat(VkPhysicalDevice physicalDevice, const TargetFormat& target);

}  // namespace crowdgpu::detail
