#pragma once
// The simplifier's view of one level of detail: its triangles over "welded" vertices, each standing
// for the model's vertices it may treat as one, and the way back to the model's own vertices.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "model/skinned_model.h"

namespace model {

// Which attribute changes the simplifier must keep as seams. meshoptimizer finds seams by position
// (vertices in one place with different data) and slides a seam vertex only along its seam; where
// three or more meet (a box corner) it cannot move the vertex at all. Material, texture-coordinate
// and skin changes are always seams: a triangle must not blend two colours, span two texture charts,
// or stretch between parts that move apart.
struct LodSeams {
    // Normal splits (creases: the edges of a flat-shaded box, a tube's cap). Kept, they keep thin
    // boxes boxes; welded, a mesh flat-shaded all over (the Fox: its own vertex per triangle corner,
    // so every vertex is a corner) becomes one surface the simplifier can reduce at all.
    bool normals = true;
    // Where the skin passes from one bending region of the skeleton to the next (model/bend_regions.h).
    // The simplifier measures its error in the bind pose only, where a straight limb looks the same
    // without the rings at its knee; bent, a limb without them folds flat, one long triangle from hip
    // to ankle. Kept as seams, such rings may lose vertices along themselves but never go away.
    bool bends = true;
};

struct WeldedMesh {
    std::vector<std::uint32_t> indices;               // triangle list over welded vertices
    std::vector<glm::vec3> positions;                 // per welded vertex
    std::vector<std::vector<std::uint32_t>> members;  // per welded vertex: the model's vertices it stands for
};

// Welds the vertices `triangles` uses (and only those: a level simplified from it reuses its vertices).
// `jointRegions` is bendRegions(model).
WeldedMesh weld(const SkinnedModel& model, const std::vector<std::uint32_t>& triangles, LodSeams seams,
                const std::vector<std::uint32_t>& jointRegions);

// Triangles over welded vertices (a simplification of mesh.indices) back on the model's vertices:
// each corner takes, among the vertices its welded vertex stands for, the one whose normal is nearest
// the triangle's (the side of a box, not its top, for a triangle on the side; ties: the earlier
// vertex). Left out: triangles without area (numerically parallel edges), repeated triangles, and
// both of a pair that is one triangle both ways round (a closed part collapsed flat).
std::vector<std::uint32_t> unweld(const SkinnedModel& model, const WeldedMesh& mesh,
                                  const std::vector<std::uint32_t>& welded);

}  // namespace model
