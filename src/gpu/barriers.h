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
// The same over a range of mip levels and array layers (the first form: mip 0, layer 0).
void imageBarrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, Access before,
                  Access after, VkImageLayout oldLayout, VkImageLayout newLayout);
void bufferBarrier(VkCommandBuffer cmd, VkBuffer buffer, Access before, Access after);

}  // namespace gpu

namespace gpu {
// A global memory barrier: for passes that hand several buffers to the next (culling's lists,
// counts and indirect commands), one barrier says it all.
void memoryBarrier(VkCommandBuffer cmd, Access before, Access after);
}  // namespace gpu
