#pragma once
// Which combinations of props get impostor cells of their own. A character's props are a mask
// (CharacterRecord.pose.z); one picture per pose serves only one mask, so a model's atlas holds a set
// of cells for each mask its characters carry, up to IMPOSTOR_SETS, the most carried first (the soldier:
// the rifle, then the rifle and the flag). A character whose mask has no set of its own (a fifth mask,
// or a set the atlas budget dropped) shows the nearest set: the one differing in the fewest props, the
// more carried on a tie. shaders/impostor_prop_set.glsl.inc is the GPU's half of the choice.
#include <cstdint>
#include <span>
#include <vector>

#include "gpu_types.h"

namespace crowd { class Crowd; }

namespace render {

// Per model of the crowd: the distinct props masks of its characters, most carried first (ties: the
// smaller mask first), at most IMPOSTOR_SETS. A model without characters gets the props most carry
// by default (model::propsMostCarry), as its pose sphere does.
std::vector<std::vector<std::uint32_t>> impostorPropSets(const crowd::Crowd& crowd);

// The set (0..its count - 1) that an impostor carrying `props` shows, among the sets `model` lists
// (cells.w of them, masks in propSets): the C++ twin of impostorPropSet in the shader.
std::uint32_t impostorPropSet(const gpu::ImpostorModel& model, std::uint32_t props);

}  // namespace render
