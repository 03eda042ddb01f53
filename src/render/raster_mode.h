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
// still draws; larger ones go to the hardware path. The default impostor threshold, so every impostor of
// its ordinary size goes to compute and only those the mesh cap demoted while large, or seen very near,
// stay on the hardware; to be set from the H100's crossover (docs/compute-raster.md, "Choosing auto's
// limit"; bench/run_compute_raster.sh).
inline constexpr float kAutoRasterLimitPixels = 32.0f;

}  // namespace render
