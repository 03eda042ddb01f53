#pragma once
// Thin helpers over vkCmdPipelineBarrier2 so each barrier in a pass reads as one line:
// what was done before (stage, access) and what comes next.
#include <vulkan/vulkan.h>

namespace gpu {

struct Access {
    VkPipelineStageFlags2 stage;
    VkAccessFlags2 access;
};

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, Access before, Access after,
                  VkImageLayout oldLayout, VkImageLayout newLayout);
void bufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, Access before, Access after);

}  // namespace gpu
