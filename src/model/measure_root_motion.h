#pragma once
// Measures how far an in-place clip would carry its character: the root-motion curve that keeps its
// planted feet still (anim/root_motion.h). Where the clip has no foot on the ground (a run's flight)
// the body keeps the cycle's mean speed; a clip whose feet never slide (idle) measures zero.
#include "anim/clip.h"
#include "anim/root_motion.h"
#include "model/skinned_model.h"

namespace model {

// Skins the mesh at evenly spaced phases of the clip; between two phases, the vertices near the
// ground at both (within 2 % of the model's height of the lowest vertex) are the planted ones, and the
// body moves by minus their median displacement. Measured in model space (x, z).
anim::RootMotion measureRootMotion(const SkinnedModel& model, const anim::Clip& clip);

}  // namespace model
