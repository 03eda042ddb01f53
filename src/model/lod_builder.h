#pragma once
// Levels of detail for a skinned model: the paper's three polygon budgets, made by meshoptimizer's
// simplifier over one vertex array whose prefixes serve the coarser levels.
#include "model/skinned_model.h"

namespace model {

// Triangle budget of level `level` for a model whose full mesh has `fullTriangles` triangles: the
// paper's ratios 1, 544/1084 and 312/1084, rounded, at least 1.
std::size_t lodTriangleTarget(std::size_t fullTriangles, std::size_t level);

// Fills model.lods with kLodLevels levels: the body (every triangle not on a prop's joint) simplified
// at the paper's budgets of its own triangle count, and each prop's own levels
// (SkinnedModel::PropPart::coarserLevels) beside it. Reorders model.vertices, model.uvs,
// model.indices and the props' levels so that level l uses exactly the vertices
// [0, lods[l].vertexCount) (level 0: all of them, its triangles in their authored order). Each body
// level is simplified from the one above with meshoptimizer
// and lands within 10 % of its budget when the mesh allows it; coarser levels only reuse vertices of
// finer ones, so every vertex keeps its skin, normal, material and uv. No level has a triangle without
// area, or a closed part collapsed into a flat sheet; a level the simplifier cannot reduce without
// that (a mesh of a few triangles: a tetrahedron keeps its four) repeats the level above it, so a
// character never loses its mesh. Deterministic; about 1 ms for the built-in models, 4 ms for 4,672
// triangles.
void buildLods(SkinnedModel& model);

}  // namespace model
