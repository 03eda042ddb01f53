#pragma once
// Where a character bends: the joints whose bones turn against their parents' in its poses, and the
// regions of the skeleton between them.
#include <cstdint>
#include <vector>

#include "model/skinned_model.h"

namespace model {

// A bone bends at its joint when, in some pose, it turns at least this far against its parent's bone,
// measured from the bind pose: less, and a limb stays straight enough for one long triangle to span
// the joint (spine segments, a wrist, an ear's twitch); more, and the surface folds there (a knee, an
// elbow, a tail's swing).
inline constexpr float kMinBendRadians = 0.35f;  // 20 degrees

// Per joint, the joint that heads its region: itself where its bone bends against its parent's (and
// for roots), else its parent's region head, so a region is a piece of the skeleton that moves as one.
// The poses looked at: the rest pose and every clip at 32 evenly spaced times.
std::vector<std::uint32_t> bendRegions(const SkinnedModel& model);

}  // namespace model
