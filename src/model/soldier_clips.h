#pragma once
// The soldier's clips: "idle", "walk" and "run", baked over its finished mesh and skeleton.
#include <vector>

#include "anim/clip.h"
#include "model/skinned_model.h"

namespace model {

// Needs the model's mesh and skeleton (the gaits keep the lowest vertex on the ground).
std::vector<anim::Clip> makeSoldierClips(const SkinnedModel& soldier);

}  // namespace model
