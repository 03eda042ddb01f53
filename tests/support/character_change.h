#pragma once
// How much one character's picture changes from one frame to the next (issue 19's tests of impostor
// blending and of fades): its pixels are those its tint changes, found by rendering it twice.
#include <vector>

#include "app/png_writer.h"

namespace test {

// The pixels a character covers: those its tint changes (a picture at tint 1 against the same at 0.6).
std::vector<bool> characterMask(const app::Rgba8Image& lit, const app::Rgba8Image& dim);

// The mean absolute difference, over RGB in 8-bit levels, of two frames over the pixels the character
// covers in either.
double characterChange(const app::Rgba8Image& a, const app::Rgba8Image& b, const std::vector<bool>& maskA,
                       const std::vector<bool>& maskB);

}  // namespace test
