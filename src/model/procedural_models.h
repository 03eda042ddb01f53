#pragma once
// Built-in characters generated in code, so the renderer runs with no asset files.
#include <cstdint>

#include "model/skinned_model.h"

namespace model {

// A humanoid soldier (helmet, head, torso, arms, legs) of about 1,084 triangles with clips "idle",
// "walk" and "run", carrying two props (model/attach_prop.h): prop 0 a rifle in the right hand, prop 1
// a flag in the left, which one soldier in eight of a crowd carries. The same seed gives the same model,
// bit for bit.
SkinnedModel makeSoldier(std::uint32_t seed = 1, bool props = true);

// A horse (body, neck, head, four legs, tail) with clips "walk" and "gallop".
SkinnedModel makeHorse(std::uint32_t seed = 1);

}  // namespace model
