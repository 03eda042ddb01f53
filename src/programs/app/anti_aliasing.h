#pragma once
// --aa: the picture's anti-aliasing. Multisampling (msaaN) covers every edge the colour pass draws
// with the hardware (characters, impostors, ground) with no history to ghost and no blur of texture;
// the samples are resolved (averaged) into the single-sample image that is written or presented. The
// library's edge filter (fxaa) anti-aliases the finished picture in compute, FXAA-like, what the
// compute rasterizer draws included; msaaN+fxaa does both.
#include <string>

#include <vulkan/vulkan.h>

namespace app {

class HostDevice;

struct AntiAliasing {
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // of the colour pass
    bool edgeFilter = false;                                // crowdgpu::RendererSettings::edgeFilter
};

// The programs' default, in this one place. Off: on the H100/H200, where the raster slice is the wall,
// every sample is a fill: 2 samples cost 46-50 % of paper-fig4's frame with `compute` and 21 % of stress
// 100,000 inside (4 samples: 137-142 % and 56 %), against the 15 %; the edge filter costs a few
// per cent but gains less; every published frame time is without anti-aliasing too. What each choice
// gains and costs is in docs/picture-quality.md.
inline constexpr AntiAliasing kDefaultAntiAliasing{};

// "off", "msaa2", "msaa4", "msaa8": the sample counts' names.
const char* antiAliasingName(VkSampleCountFlagBits samples);
// Those, "fxaa" and "msaaN+fxaa": the names --aa takes and reports print.
std::string antiAliasingName(AntiAliasing antiAliasing);
// Throws app::Error naming `flag` for anything but those names.
AntiAliasing parseAntiAliasing(const std::string& flag, const std::string& text);
// Throws app::Error (one line naming --aa, the device and what it can do) when the device cannot
// render colour and depth with this many samples per pixel.
void checkAntiAliasing(const HostDevice& device, VkSampleCountFlagBits samples);

}  // namespace app
