#pragma once
// Which rasterizer draws the impostors (docs/compute-raster.md): the hardware's (the frame as before
// the compute rasterizer), the compute rasterizer's visibility buffer, or each impostor by its size on
// screen (auto: small ones in compute, large ones on the hardware, decided per impostor on the GPU).
#include <cstdint>
#include <optional>
#include <string_view>

namespace gpu { class VulkanContext; }

namespace render {

enum class RasterMode { Hardware, Compute, Auto };

// "hardware", "compute", "auto".
const char* rasterModeName(RasterMode mode);
std::optional<RasterMode> parseRasterMode(std::string_view name);

// Throws gpu::Error(Unsupported) in one line when the compute rasterizers (impostors, meshes) cannot run:
// the device lacks (or was created without) 64-bit integers and buffer atomics. A multisampled target
// is drawn: the resolve writes a covered pixel's colour and depth to all its samples (one visibility
// word a pixel), so what compute draws is merged by depth but its own edges are not anti-aliased.
void requireComputeRaster(const gpu::VulkanContext& context);

// Under auto, the longest side (pixels) of an impostor's screen rectangle that the compute rasterizer
// still draws; larger ones go to the hardware path. Set from the H100's sweep (docs/compute-raster.md,
// "Choosing auto's limit"; bench/results/h100-2026-11-24-compute-raster): compute was faster per impostor
// at every size measured, from 3 px (3.1x) to 187 px a side (1.2x), so no crossover was found; 128 px
// keeps to the measured range with a margin (0.6x of the hardware's time at 96 px).
inline constexpr float kAutoRasterLimitPixels = 128.0f;

// Small characters' meshes under auto (render/mesh_raster.h, docs/compute-raster.md "Meshes"). The mesh
// path has fixed costs (a raster pass and a full-screen resolve: 0.3-0.5 ms at 1080p on the H100) and
// pays off only when the hardware rasterizer is the wall, so auto engages it for a frame when that frame
// slot's previous frame drew at least kAutoMeshRasterMinTriangles mesh triangles (about 4 ms on the H100's
// graphics slice, 1 G triangles/s), for characters up to kAutoMeshRasterLimitPixels across (pose sphere).
// Measured (bench/results/h100-2026-11-24-mesh-raster): at 64 px, 250,000 all-mesh soldiers inside the
// crowd (24.7 M triangles) went from 34 to 144 fps and stress 100,000 inside (10.7 M) from 66 to 163,
// while paper-fig4 (1.0 M) and the default scene (0.56 M) lost 11-14 % with the path always on.
inline constexpr float kAutoMeshRasterLimitPixels = 64.0f;
inline constexpr std::uint64_t kAutoMeshRasterMinTriangles = 4'000'000;
// A mesh limit that asks for that automatic choice (RendererSettings::meshRasterLimit's default); a limit
// of 0 or more is used every frame (0: no mesh in compute under auto).
inline constexpr float kMeshRasterAutomatic = -1.0f;

}  // namespace render
