#pragma once
// A clip's skinning matrices at one time, on the CPU in float: what the model-build analyses (root motion
// measured from the feet, footstep detection) skin the mesh with.
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"
#include "model/skinned_model.h"

namespace model {

// Per joint: its model-space matrix at `time` seconds into `clip` times its inverse bind.
std::vector<glm::mat4> clipSkinningMatrices(const SkinnedModel& model, const anim::Clip& clip, float time);

}  // namespace model
