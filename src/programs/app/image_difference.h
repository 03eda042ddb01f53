#pragma once
// How far one picture is from another: the peak signal-to-noise ratio over the colour channels (alpha
// left out), the measure the issue reports (docs/impostors.md, bench/run_capacity.sh).
#include <cstdint>

#include "app/png_writer.h"

namespace app {

struct ImageDifference {
    double meanSquaredError = 0.0;  // per colour channel, in 8-bit levels squared
    double psnr = 0.0;              // dB: 10 log10(255^2 / MSE); infinite for equal pictures
    std::uint64_t differingPixels = 0;  // pixels with any colour channel different
};

// The pictures must have the same size (throws app::Error otherwise).
ImageDifference compareImages(const app::Rgba8Image& a, const app::Rgba8Image& b);

}  // namespace app
