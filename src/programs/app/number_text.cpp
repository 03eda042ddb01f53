#include "app/number_text.h"

#include <cstdio>
#include <iterator>

#include <array>
#include <charconv>

namespace app {

std::string formatNumber(float value) {
    // A float in fixed notation has at most 39 integer digits and 150 or so after the point.
    std::array<char, 192> text{};
    const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed);
    return error == std::errc() ? std::string(text.data(), end) : std::to_string(value);
}

std::string formatNumber(double value) {
    // A double in fixed notation has at most 309 integer digits and 1074 or so after the point.
    std::array<char, 1400> text{};
    const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed);
    return error == std::errc() ? std::string(text.data(), end) : std::to_string(value);
}

std::string formatBytes(std::uint64_t bytes) {
    static const char* const units[] = {"KiB", "MiB", "GiB", "TiB"};
    if (bytes < 1024) return std::to_string(bytes) + " B";
    double scaled = static_cast<double>(bytes) / 1024.0;
    std::size_t unit = 0;
    for (; scaled >= 1024.0 && unit + 1 < std::size(units); ++unit) scaled /= 1024.0;
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %s", scaled, units[unit]);
    return text;
}

}  // namespace app
