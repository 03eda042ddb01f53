#pragma once
// A supersampled picture brought down to the size it stands for: each `factor` x `factor` block of
// pixels averaged into one (a box filter), the reference anti-aliasing is measured against (issue 19:
// render at 4x the width and height, box-filter down). The averaging is in linear light, as light
// adds up over a pixel: the sRGB-encoded bytes are decoded, averaged and encoded again.
#include <cstdint>

#include "app/png_writer.h"

namespace app {

// A linear value (0..1, clamped) as an sRGB-encoded 8-bit level, rounded.
std::uint8_t encodeSrgb(double linear);

// Throws app::Error when the picture's width or height is not a multiple of `factor` (or factor is 0).
Rgba8Image boxDownsample(const Rgba8Image& image, std::uint32_t factor);

}  // namespace app
