#include "app/anti_aliasing.h"

#include "app/error.h"
#include "app/host_device.h"

namespace app {
namespace {

constexpr VkSampleCountFlagBits kChoices[] = {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_2_BIT, VK_SAMPLE_COUNT_4_BIT,
                                              VK_SAMPLE_COUNT_8_BIT};

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

VkSampleCountFlagBits parseAntiAliasing(const std::string& flag, const std::string& text) {
    for (VkSampleCountFlagBits samples : kChoices)
        if (text == antiAliasingName(samples)) return samples;
    throw Error(flag + ": '" + text + "' is not off, msaa2, msaa4 or msaa8");
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
