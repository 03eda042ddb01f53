#include "app/anti_aliasing.h"

#include "app/error.h"
#include "app/host_device.h"

namespace app {
namespace {

constexpr VkSampleCountFlagBits kChoices[] = {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_2_BIT, VK_SAMPLE_COUNT_4_BIT,
                                              VK_SAMPLE_COUNT_8_BIT};
// The edge filter's name: FXAA is what users know the method by (this one is the library's own code).
constexpr const char* kEdgeFilterName = "fxaa";

}  // namespace

const char* antiAliasingName(VkSampleCountFlagBits samples) {
    switch (samples) {
    case VK_SAMPLE_COUNT_1_BIT: return "off";
    case VK_SAMPLE_COUNT_2_BIT: return "msaa2";
    case VK_SAMPLE_COUNT_4_BIT: return "msaa4";
    case VK_SAMPLE_COUNT_8_BIT: return "msaa8";
    default: return "unknown";
    }
}

std::string antiAliasingName(AntiAliasing antiAliasing) {
    if (!antiAliasing.edgeFilter) return antiAliasingName(antiAliasing.samples);
    if (antiAliasing.samples == VK_SAMPLE_COUNT_1_BIT) return kEdgeFilterName;
    return antiAliasingName(antiAliasing.samples) + std::string("+") + kEdgeFilterName;
}

AntiAliasing parseAntiAliasing(const std::string& flag, const std::string& text) {
    for (const bool edgeFilter : {false, true})
        for (VkSampleCountFlagBits samples : kChoices)
            if (text == antiAliasingName(AntiAliasing{samples, edgeFilter})) return {samples, edgeFilter};
    throw Error(flag + ": '" + text + "' is not off, msaa2, msaa4, msaa8, fxaa or msaaN+fxaa");
}

void checkAntiAliasing(const HostDevice& device, VkSampleCountFlagBits samples) {
    // The target has both: the colour and the depth attachment must take the count.
    const VkSampleCountFlags supported = device.properties.limits.framebufferColorSampleCounts &
                                         device.properties.limits.framebufferDepthSampleCounts;
    if (supported & samples) return;
    std::string choices;
    for (VkSampleCountFlagBits choice : kChoices)
        if (supported & choice) choices += (choices.empty() ? "" : ", ") + std::string(antiAliasingName(choice));
    throw Error(std::string("--aa ") + antiAliasingName(samples) + ": " + device.description.name +
                " cannot render " + std::to_string(samples) + " samples per pixel (it can: " + choices + ")");
}

}  // namespace app
