#pragma once
// A prop: a rigid mesh that a model carries on a joint (a rifle in the hand, a flag), in its own space,
// with levels of detail of its own.
#include <array>
#include <string>
#include <vector>

#include "gpu_types.h"
#include "model/skinned_model.h"

namespace model {

// Vertices as the model's (bind-pose SkinVertex, material index in normal.w), all rigid on joint 0:
// attachProp moves them to the joint it gives the prop. Materials index materialColors.
struct PropMesh {
    std::string name;
    std::vector<gpu::SkinVertex> vertices;
    // Counter-clockwise triangles at each level of detail: levels[0] the full prop (never empty); a
    // coarser level uses only vertices of the level above it (so that the model's levels keep drawing a
    // prefix of its vertices, docs/props.md), and an empty one is not drawn at that level.
    std::array<std::vector<std::uint32_t>, kLodLevels> levels;
    std::vector<glm::vec4> materialColors;

    std::size_t triangleCount(std::size_t level = 0) const { return levels[level].size() / 3; }
};

// The built-in props, in metres. The rifle lies along +z (muzzle forward), its grip at the origin where
// a hand closes on it; the flag's pole runs along +y from the origin, where a hand holds it. Their
// coarser levels are made of level 0's vertices (whole boxes, faces of boxes, and tubes lofted between
// the ends of two boxes), so they add no vertex to skin.
PropMesh makeRifle();
PropMesh makeFlag();

// The mesh of a model with one rigid part (a prop made in code or read from a file): every vertex
// must be on joint 0 alone. Its levels are the model's (model/lod_builder.h) when built, else its
// full mesh at every level.
PropMesh propFromModel(const SkinnedModel& model);

// Checks what attachProp relies on: level 0 has triangles, every index names a vertex, every vertex is
// rigid on joint 0 and each coarser level uses only vertices of the level above. Throws gpu::Error
// "<what>: <problem>".
void checkPropMesh(const PropMesh& prop, const std::string& what);

}  // namespace model
