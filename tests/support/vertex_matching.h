#pragma once
// app::loadModel reorders a model's vertices for its levels of detail (model::buildLods). Tests that
// compare its vertices with the file's, or with the model as built, match them up here.
#include <cstdint>
#include <vector>

#include "model/skinned_model.h"

namespace test {

// For each vertex of `reordered`, the index of the vertex of `original` it is: the same bind-pose
// data and texture coordinates. Vertices that are exact copies of each other are matched in order, so
// the result is a permutation. ~0u for a vertex `original` does not have.
std::vector<std::uint32_t> originalVertexOf(const model::SkinnedModel& original, const model::SkinnedModel& reordered);

}  // namespace test
