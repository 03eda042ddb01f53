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
// still draws; larger ones go to the hardware path. Set from the H100's sweep (docs/compute-raster.md,
// "Choosing auto's limit"; bench/results/h100-2026-11-24-compute-raster): compute was faster per impostor
// at every size measured, from 3 px (3.1x) to 187 px a side (1.2x), so no crossover was found; 128 px
// keeps to the measured range with a margin (0.6x of the hardware's time at 96 px).
inline constexpr float kAutoRasterLimitPixels = 128.0f;

// Under auto, the largest character (its pose sphere's diameter on screen, pixels) whose mesh the
// compute rasterizer draws (render/mesh_raster.h); larger ones, and every one under raster hardware,
// go to the hardware path. 0: under auto, meshes stay on the hardware unless the host asks
// (RendererSettings::meshRasterLimit, --mesh-raster-limit). Measured on the H100 (docs/compute-raster.md,
// "Meshes"; bench/results/h100-2026-11-24-mesh-raster): 64 px takes 250,000 all-mesh soldiers inside the
// crowd from 34 to 144 fps, but costs light frames (paper-fig4, the default scene) 8-14 %, where the
// hardware draw does not shrink and the raster pass and full-screen resolve add 0.3-0.5 ms.
inline constexpr float kAutoMeshRasterLimitPixels = 0.0f;

}  // namespace render
