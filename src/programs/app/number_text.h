#pragma once
// Numbers in messages, written the way a person writes them: 0..1000000, 0.5, 12.25 (not
// 0.000000..1000000.000000 as std::to_string prints a float, nor 1e+06 as %g does).
#include <cstdint>
#include <string>

namespace app {

// The shortest fixed-point text that reads back as `value` (no exponent, no trailing zeros).
std::string formatNumber(float value);
std::string formatNumber(double value);

// Bytes in binary units with one decimal: "1.5 GiB", "12.0 MiB", "512 B".
std::string formatBytes(std::uint64_t bytes);

}  // namespace app
