#pragma once
// Footstep events for clips whose feet walk: each foot's touchdown, the moment its lowest vertex
// reaches the ground and stops there, found on the skinned mesh carried by the clip's root motion
// (docs/events.md#footsteps).
#include <cstdint>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "model/skinned_model.h"

namespace model {

// The name every footstep event carries; its ClipEvent::joint says which foot.
inline constexpr const char* kFootstepEvent = "footstep";

// The touchdowns of each foot in `feet` (joints of the model; a foot is the joint and the joints under it) over
// one cycle of `clip`: one event per foot per step it takes, none for a foot that never leaves the
// ground (idle). In time order.
std::vector<anim::ClipEvent> findFootsteps(const SkinnedModel& model, const anim::Clip& clip,
                                           const std::vector<std::uint32_t>& feet);

// Adds the footsteps of the joints named `footJoints` to every clip of `model`, merged in time order
// with the events it has. The built-in models call it once their clips are baked.
void attachFootsteps(SkinnedModel& model, const std::vector<std::string>& footJoints);

}  // namespace model
