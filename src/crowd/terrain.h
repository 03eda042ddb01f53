#pragma once
// The ground the host gives (docs/host-driven.md, "Terrain"): a heightfield, heights on a regular grid
// over a rectangle of the ground, bilinear between the samples and the edge's heights beyond it. Every
// character stands on it (its height added to the character's own y), whatever moves it; the renderer
// draws the library's ground as it. The rules are shaders/terrain_height.h's, so the CPU's heights are
// the GPU's.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace crowd {

struct Heightfield {
    std::uint32_t columns = 0, rows = 0;  // samples along x and along z (at least 2 each)
    std::vector<float> heights;           // metres, row-major: sample (column, row) at column + row x columns
    glm::vec2 origin{0.0f};               // world (x, z) of sample (0, 0)
    glm::vec2 size{0.0f};                 // world width (x) and depth (z) of the grid: the last sample at origin + size
};

class Terrain {
public:
    // Flat: the plane y = 0.
    Terrain() = default;
    // Throws gpu::Error (InvalidArgument) for fewer than 2 x 2 samples, more than 2^25, heights that do not
    // fill the grid or are not finite, or an extent that is not positive and finite.
    explicit Terrain(Heightfield field);

    bool flat() const { return field_.heights.empty(); }
    float height(glm::vec2 ground) const;
    // The grid as the shaders read it (extent z = 0 when flat), and its heights.
    gpu::TerrainGrid grid() const;
    const std::vector<float>& heights() const { return field_.heights; }
    float lowest() const { return lowest_; }
    float highest() const { return highest_; }
    const Heightfield& field() const { return field_; }

private:
    Heightfield field_;
    float lowest_ = 0.0f, highest_ = 0.0f;
};

}  // namespace crowd
