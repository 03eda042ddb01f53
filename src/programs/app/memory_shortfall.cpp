#include "app/memory_shortfall.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "app/number_text.h"

namespace app {
namespace {

// `a` and `b` in the larger one's binary unit, with one decimal or as many more as it takes for them
// to read differently (down to whole bytes): "2.0 GiB" against "2.0 GiB" says nothing.
std::pair<std::string, std::string> formatBytesApart(std::uint64_t a, std::uint64_t b) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    int unit = 0;
    double scale = 1.0;
    while (static_cast<double>(std::max(a, b)) / scale >= 1024.0 && unit < 4) scale *= 1024.0, ++unit;
    const auto format = [&](std::uint64_t bytes, int decimals) {
        char text[64];
        std::snprintf(text, sizeof text, "%.*f %s", decimals, static_cast<double>(bytes) / scale, units[unit]);
        return std::string(text);
    };
    int decimals = unit == 0 ? 0 : 1;
    while (decimals < 13 && format(a, decimals) == format(b, decimals)) ++decimals;  // 13: TiB to the byte
    return {format(a, decimals), format(b, decimals)};
}

}  // namespace

std::string describeShortfall(const MemoryShortfall& s) {
    const auto [needed, available] = formatBytesApart(s.needed, s.available);
    const bool imageOverflows = s.needed - s.imageBytes <= s.available;
    if (imageOverflows) {
        return "--size " + std::to_string(s.size.width) + "x" + std::to_string(s.size.height) + ": the image needs " +
               app::formatBytes(s.imageBytes) + " of device memory besides the crowd's " +
               app::formatBytes(s.needed - s.imageBytes) + ", " + needed + " in all; " + s.device + " has " + available;
    }
    return "--count " + std::to_string(s.count) + ": " + s.method + " needs about " + needed + " of device memory; " +
           s.device + " has " + available;
}

}  // namespace app
