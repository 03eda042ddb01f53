#include "app/terrain_hills.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/error.h"

namespace app {
namespace {

struct Wave {
    float amplitude;   // metres
    float wavelength;  // metres
    float direction;   // radians from +x
    float phase;       // radians
};

// Long rolling hills with a few shorter undulations: the sum of amplitude x 2 pi / wavelength is 0.340 (18.8 degrees).
constexpr Wave kWaves[] = {{1.0f, 40.0f, 0.3f, 0.0f},
                           {0.5f, 27.0f, 1.9f, 1.1f},
                           {0.15f, 17.0f, 4.0f, 2.3f},
                           {0.02f, 11.0f, 5.3f, 0.4f}};

}  // namespace

float hillsHeight(float x, float z) {
    float h = 0.0f;
    for (const Wave& w : kWaves) {
        const float k = 2.0f * std::numbers::pi_v<float> / w.wavelength;
        h += w.amplitude * std::sin(k * (x * std::cos(w.direction) + z * std::sin(w.direction)) + w.phase);
    }
    return h;
}

float hillsSteepestDegrees() {
    float slope = 0.0f;
    for (const Wave& w : kWaves) slope += w.amplitude * 2.0f * std::numbers::pi_v<float> / w.wavelength;
    return std::atan(slope) * 180.0f / std::numbers::pi_v<float>;
}

crowdgpu::Heightfield TerrainSamples::heightfield() const {
    crowdgpu::Heightfield field;
    field.columns = columns, field.rows = rows, field.heights = heights.data();
    field.origin[0] = origin[0], field.origin[1] = origin[1];
    field.size[0] = size[0], field.size[1] = size[1];
    return field;
}

TerrainSamples hillsAround(float x, float z, float halfExtent) {
    TerrainSamples t;
    const float side = 2.0f * std::max(halfExtent, 1.0f);
    const float spacing = std::max(0.5f, side / 4095.0f);
    t.columns = t.rows = static_cast<std::uint32_t>(std::ceil(side / spacing)) + 1u;
    const float extent = spacing * static_cast<float>(t.columns - 1);
    t.origin[0] = x - 0.5f * extent, t.origin[1] = z - 0.5f * extent;
    t.size[0] = t.size[1] = extent;
    t.heights.resize(std::size_t{t.columns} * t.rows);
    for (std::uint32_t r = 0; r < t.rows; ++r)
        for (std::uint32_t c = 0; c < t.columns; ++c)
            t.heights[std::size_t{r} * t.columns + c] =
                hillsHeight(t.origin[0] + spacing * static_cast<float>(c), t.origin[1] + spacing * static_cast<float>(r));
    return t;
}

float steepestDegrees(const TerrainSamples& t) {
    const float dx = t.size[0] / static_cast<float>(t.columns - 1), dz = t.size[1] / static_cast<float>(t.rows - 1);
    float steepest = 0.0f;
    for (std::uint32_t r = 0; r + 1 < t.rows; ++r)
        for (std::uint32_t c = 0; c + 1 < t.columns; ++c) {
            const float h = t.heights[std::size_t{r} * t.columns + c];
            steepest = std::max({steepest, std::abs(t.heights[std::size_t{r} * t.columns + c + 1] - h) / dx,
                                 std::abs(t.heights[std::size_t{r + 1} * t.columns + c] - h) / dz});
        }
    return std::atan(steepest) * 180.0f / std::numbers::pi_v<float>;
}

bool parseTerrain(const std::string& flag, const std::string& value) {
    if (value == "hills") return true;
    if (value == "flat") return false;
    throw Error(flag + ": '" + value + "' is not flat or hills");
}

}  // namespace app
