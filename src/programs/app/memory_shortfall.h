#pragma once
// The one line that says a crowd does not fit in device memory: which flag to change, and figures
// that show the shortfall (two sizes that round to the same text would not).
#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

namespace app {

struct MemoryShortfall {
    std::uint32_t count = 0;        // characters (--count)
    VkExtent2D size{0, 0};          // image (--size)
    std::string method;             // skinning method's name
    std::uint64_t needed = 0;       // bytes the whole run needs
    std::uint64_t imageBytes = 0;   // of which the image's targets
    std::uint64_t available = 0;    // the device's largest device-local heap
    std::string device;
};

// "--size WxH: ..." when the crowd alone would fit and the image is what overflows, else
// "--count N: ...", each with the needed and available bytes to as many decimals as they take to differ.
std::string describeShortfall(const MemoryShortfall& s);

}  // namespace app
