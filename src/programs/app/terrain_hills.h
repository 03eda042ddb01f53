#pragma once
// --terrain hills: a built-in, deterministic hilly ground for any scene (docs/host-driven.md, "Terrain"):
// four long waves across the ground, whose slopes add up to at most 19 degrees (tan 19 = 0.344 >= the
// sum of each wave's amplitude times its wavenumber), sampled on a grid over the scene's ground.
#include <cstdint>
#include <string>
#include <vector>

#include <crowdgpu/crowd.hpp>

namespace app {

// The hills' height at (x, z), metres.
float hillsHeight(float x, float z);
// The steepest the hills can be anywhere, degrees (the bound the waves were chosen under).
float hillsSteepestDegrees();

// A heightfield of the hills over the square of half side `halfExtent` around (x, z): samples every half
// metre, or coarser past 4,096 a side.
struct TerrainSamples {
    std::uint32_t columns = 0, rows = 0;
    std::vector<float> heights;
    float origin[2] = {0.0f, 0.0f};
    float size[2] = {0.0f, 0.0f};
    crowdgpu::Heightfield heightfield() const;
};
TerrainSamples hillsAround(float x, float z, float halfExtent);

// The steepest slope between neighbouring samples of a heightfield, degrees.
float steepestDegrees(const TerrainSamples& terrain);

// "flat" or "hills" (--terrain); throws app::Error for anything else.
bool parseTerrain(const std::string& flag, const std::string& value);

}  // namespace app
