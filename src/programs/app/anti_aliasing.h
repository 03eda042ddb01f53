#pragma once
// --aa: the colour pass's samples per pixel. Multisampling covers every edge the colour pass draws
// (characters, impostors, ground) at once, with no history to ghost and no blur of the texture; the
// samples are resolved (averaged) into the single-sample image that is written or presented.
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

// The programs' default, in this one place so that a measurement of its cost (bench/run_aa.sh) can
// move it: what each count gains against a 4x4 supersampled render, and costs, is in
// docs/picture-quality.md.
inline constexpr VkSampleCountFlagBits kDefaultSamples = VK_SAMPLE_COUNT_4_BIT;

// "off", "msaa2", "msaa4", "msaa8": the names --aa takes and reports print.
const char* antiAliasingName(VkSampleCountFlagBits samples);
// Throws app::Error naming `flag` for anything but those names.
VkSampleCountFlagBits parseAntiAliasing(const std::string& flag, const std::string& text);
// Throws app::Error (one line naming --aa, the device and what it can do) when the device cannot
// render colour and depth with this many samples per pixel.
void checkAntiAliasing(const HostDevice& device, VkSampleCountFlagBits samples);

}  // namespace app
