#pragma once
// Records commands into a temporary command buffer, submits them and waits: for uploads and readbacks
// outside the frame loop.
#include <functional>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

// The submission ends with a full memory barrier to the host, so anything it wrote is visible to
// later submissions and to mapped reads once this returns.
void runOneShot(const VulkanContext& context, const std::function<void(VkCommandBuffer)>& record);

}  // namespace gpu
