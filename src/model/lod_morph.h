#pragma once
// Geomorphs between levels of detail: where each vertex of a level goes as its character fades into
// the next coarser level, so that a level change is a continuous change of shape over the fade band
// (docs/picture-quality.md, "No pops") instead of two levels dithered over each other.
//
// The levels nest (model/lod_builder.h): level l + 1 uses the vertices [0, lods[l + 1].vertexCount), a
// prefix of level l's. The vertices level l adds, [lods[l + 1].vertexCount, lods[l].vertexCount), are
// the ones that move: each goes to the nearest point of level l + 1's surface around it. Skinned, that
// point is the same blend of its triangle's three skinned corners, which the coarser level draws there,
// so a fully morphed level l covers what level l + 1 covers and shades as it does (its normals morph
// too). Texture coordinates stay the vertex's own.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "model/skinned_model.h"

namespace model {

// One vertex's place on the next coarser level's surface: the point of triangle `corners` (model
// vertex indices, all used by that level) with barycentric weights (1 - w.x - w.y, w.x, w.y). A vertex
// that does not move (the coarsest level's, or one no triangle uses) targets itself: corners all v,
// weights 0.
struct LodMorphTarget {
    std::array<std::uint32_t, 3> corners{};
    glm::vec2 weights{0.0f};
};

// For every vertex of `model`: vertex v in [lods[l + 1].vertexCount, lods[l].vertexCount) that level l
// draws targets the nearest point of a level l + 1 triangle near it on the surface: among the coarser
// triangles around the coarser vertices the fewest edges of level l away from v (and one edge
// further), on the same part (the body, or the same prop: props are rigid on their own joints), the
// one nearest v in the bind pose. Vertices at one position (seams) count as one on the way. `lods` has
// one entry per level (render::lodsOf pads a model without levels by repeating its mesh: nothing then
// moves). Deterministic.
std::vector<LodMorphTarget> lodMorphTargets(const SkinnedModel& model, const std::vector<SkinnedModel::Lod>& lods);

// A target as the GPU reads it (gpu_types.h, LodMorphTarget): xyz the corners, w the two weights as
// unorm16 (x in the low half), as GLSL's packUnorm2x16 writes them.
glm::uvec4 packLodMorphTarget(const LodMorphTarget& target);

}  // namespace model
