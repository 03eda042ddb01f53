#include "crowd/terrain.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gpu/error.h"

namespace crowd {
namespace rules {

using namespace glm;
using gpu::TerrainGrid;
using gpu::uint;

#include "terrain_height.h"

}  // namespace rules

namespace {

// Samples a heightfield may have: 2^25 floats are 128 MiB, every device's guaranteed storage-buffer range
// (maxStorageBufferRange's minimum), and a 5,792 x 5,792 grid: a metre a sample over 33 km^2.
constexpr std::uint64_t kMostSamples = std::uint64_t{1} << 25;

}  // namespace

Terrain::Terrain(Heightfield field) : field_(std::move(field)) {
    const std::uint64_t samples = std::uint64_t{field_.columns} * field_.rows;
    if (field_.columns < 2 || field_.rows < 2 || samples > kMostSamples)
        throw gpu::Error("terrain: " + std::to_string(field_.columns) + " x " + std::to_string(field_.rows) +
                         " samples; a heightfield has 2 x 2 to 2^25 of them");
    if (field_.heights.size() != samples)
        throw gpu::Error("terrain: " + std::to_string(field_.heights.size()) + " heights for a grid of " +
                         std::to_string(field_.columns) + " x " + std::to_string(field_.rows));
    if (!(field_.size.x > 0.0f && field_.size.y > 0.0f && std::isfinite(field_.size.x) && std::isfinite(field_.size.y) &&
          std::isfinite(field_.origin.x) && std::isfinite(field_.origin.y)))
        throw gpu::Error("terrain: the extent must be positive and finite (origin (" + std::to_string(field_.origin.x) +
                         ", " + std::to_string(field_.origin.y) + "), size " + std::to_string(field_.size.x) + " x " +
                         std::to_string(field_.size.y) + " m)");
    const auto bad = std::find_if(field_.heights.begin(), field_.heights.end(), [](float h) { return !std::isfinite(h); });
    if (bad != field_.heights.end()) {
        const auto at = static_cast<std::uint64_t>(bad - field_.heights.begin());
        throw gpu::Error("terrain: the height of sample (" + std::to_string(at % field_.columns) + ", " +
                         std::to_string(at / field_.columns) + ") is not finite");
    }
    const auto [lo, hi] = std::minmax_element(field_.heights.begin(), field_.heights.end());
    lowest_ = *lo, highest_ = *hi;
}

gpu::TerrainGrid Terrain::grid() const {
    if (flat()) return {glm::vec4(0.0f), glm::uvec4(2u, 2u, 0u, 0u)};
    return {glm::vec4(field_.origin, field_.size), glm::uvec4(field_.columns, field_.rows, 0u, 0u)};
}

float Terrain::height(glm::vec2 ground) const {
    if (flat()) return 0.0f;
    const rules::TerrainCell cell = rules::terrainCellOf(grid(), ground);
    const float* h = field_.heights.data() + cell.first;
    return rules::terrainBlend(h[0], h[1], h[field_.columns], h[field_.columns + 1], cell.fraction);
}

}  // namespace crowd
