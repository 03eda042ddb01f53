#pragma once
// --aa: the colour pass's samples per pixel. Multisampling covers every edge the colour pass draws
// (characters, impostors, ground) at once, with no history to ghost and no blur of the texture; the
// samples are resolved (averaged) into the single-sample image that is written or presented.
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

// The programs' default, in this one place. Off: on the H100, where the raster slice is the wall, 4
// samples cost 77 % of paper-fig4's frame with `compute` and 24 % of stress 100,000's (2 samples: 29 %
// and 12 %), against the 15 %; every published frame time is single-sampled too. `--aa msaa4`
// gains 3.1-3.6 dB against a 4x4 supersampled render (5.9 dB on a far crowd of impostors): what each
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
