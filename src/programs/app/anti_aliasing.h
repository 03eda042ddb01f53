#pragma once
// --aa: the colour pass's samples per pixel. Multisampling covers every edge the colour pass draws
// (characters, impostors, ground) at once, with no history to ghost and no blur of the texture; the
// samples are resolved (averaged) into the single-sample image that is written or presented.
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

// The programs' default, in this one place. Off: on the H100/H200, where the raster slice is the wall,
// every sample is a fill: 2 samples cost 46-50 % of paper-fig4's frame with `compute` and 21 % of stress
// 100,000 inside (4 samples: 137-142 % and 56 %), against the 15 %; every published frame time
// is single-sampled too. `--aa msaa4` gains 2.8-3.5 dB against a 4x4 supersampled render: what each
// count gains and costs is in docs/picture-quality.md.
inline constexpr VkSampleCountFlagBits kDefaultSamples = VK_SAMPLE_COUNT_1_BIT;

// "off", "msaa2", "msaa4", "msaa8": the names --aa takes and reports print.
const char* antiAliasingName(VkSampleCountFlagBits samples);
// Throws app::Error naming `flag` for anything but those names.
VkSampleCountFlagBits parseAntiAliasing(const std::string& flag, const std::string& text);
// Throws app::Error (one line naming --aa, the device and what it can do) when the device cannot
// render colour and depth with this many samples per pixel.
void checkAntiAliasing(const HostDevice& device, VkSampleCountFlagBits samples);

}  // namespace app
