#pragma once
// The formats and sample count of the pass the crowd is drawn into: the host's, on a borrowed device;
// the offscreen target's in the programs. Every colour-pass pipeline is built for them.
#include <vulkan/vulkan.h>

namespace render {

struct TargetFormat {
    VkFormat color = VK_FORMAT_R8G8B8A8_SRGB;
    VkFormat depth = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

}  // namespace render
