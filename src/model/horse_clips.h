#pragma once
// The horse's clips: "walk" and "gallop", baked over its finished mesh and skeleton.
#include <vector>

#include "anim/clip.h"
#include "model/skinned_model.h"

namespace model {

// Needs the model's mesh and skeleton (the gaits keep the lowest hoof on the ground).
std::vector<anim::Clip> makeHorseClips(const SkinnedModel& horse);

}  // namespace model
