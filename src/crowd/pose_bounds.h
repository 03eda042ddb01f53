#pragma once
// The sphere that holds a character in every pose its clips can give it: what culling tests. Found
// once per model by skinning each clip on the CPU at many times.
#include <glm/glm.hpp>

#include "model/skinned_model.h"

namespace crowd {

// A sphere in model space (xyz centre, w radius) holding every skinned vertex of the rest pose and of
// every clip at any time. Each clip is sampled at every key time of every channel and 60 times a
// second; the centre is that of the samples' bounding box, and the radius the farthest sample plus
// 1 % for poses between samples. Zero for a model without vertices. Costs one CPU skinning of the
// model's distinct (position, skin) vertices per sample: 5 to 20 ms for the built-in and shared models
// (the soldier, with 4.8 s of clips, about 10 ms; CesiumMan, 2,338 distinct vertices, about 20 ms).
glm::vec4 computePoseSphere(const model::SkinnedModel& model);

}  // namespace crowd
