#include "app/number_text.h"

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

}  // namespace app
