#pragma once
// The sphere that holds a character in every pose its clips can give it: what culling tests. Found
// once per model by skinning each clip on the CPU at many times.
#include <cstdint>

#include <glm/glm.hpp>

#include "model/skinned_model.h"

namespace crowd {

// A sphere in model space (xyz centre, w radius) holding every skinned vertex of the rest pose and of
// every clip at any time. Each clip is sampled at every key time of every channel and 60 times a
// second; the centre is that of the samples' bounding box, and the radius the farthest sample plus
// 1 % for poses between samples. A clip that would take more than 1,200 samples so (over 20 s, or
// with that many keys) is sampled at 1,200 evenly spaced times instead, and the sphere grown to hold
// the bound anim::poseReach puts on all its poses, so it stays conservative (and may be looser) and
// the cost stays bounded however long the clip. Zero for a model without vertices. Costs two CPU
// skinnings of the model's distinct (position, skin) vertices per sample, memory for one pose: 5 to
// 40 ms for the built-in and shared models (the soldier, with 4.8 s of clips, about 20 ms).
glm::vec4 computePoseSphere(const model::SkinnedModel& model);

// The radius about `centre` that holds every pose (sampled as above, with the same margin) of the model
// carrying the props in `carried` (bit k: prop k). The impostor cells of characters carrying a prop the
// pose sphere leaves out (the soldier's flag) are framed by it about the pose sphere's centre
// (render/impostor_atlas.h). About 20 ms for the soldier.
float poseRadiusAbout(const model::SkinnedModel& model, const glm::vec3& centre, std::uint32_t carried);

}  // namespace crowd
