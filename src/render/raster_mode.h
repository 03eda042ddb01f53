#pragma once
// Which rasterizer draws the impostors (docs/compute-raster.md): the hardware's (the frame as before
// the compute rasterizer), the compute rasterizer's visibility buffer, or each impostor by its size on
// screen (auto: small ones in compute, large ones on the hardware, decided per impostor on the GPU).
#include <optional>
#include <string_view>

namespace render {

enum class RasterMode { Hardware, Compute, Auto };

// "hardware", "compute", "auto".
const char* rasterModeName(RasterMode mode);
std::optional<RasterMode> parseRasterMode(std::string_view name);

// Under auto, the longest side (pixels) of an impostor's screen rectangle that the compute rasterizer
// still draws; larger ones go to the hardware path. Chosen from the measured crossover
// (docs/compute-raster.md, bench/run_compute_raster.sh).
inline constexpr float kAutoRasterLimitPixels = 64.0f;

}  // namespace render
