#pragma once
// A rider on a mount as one skinned character: the mount's skeleton and mesh, then the rider's, its
// roots parented to the mount's saddle joint, so culling, levels of detail, shadows, impostors, motion,
// crossfades and every skinning method treat the pair as one character and the two never drift apart.
#include <cstdint>
#include <string>
#include <vector>

#include "model/skinned_model.h"

namespace model {

// Prefix of the rider's joint names in a mounted skeleton ("rider_hips", "rider_hand_r", ...): the
// mount's keep their names, and the two sets cannot collide (both may have a "head").
inline constexpr const char* kRiderJointPrefix = "rider_";

// The mounted model, named `name`. The rider sits with its root joint above the saddle joint, at the
// height that puts the lowest vertex its root carries on the saddle. Clips: the mount's, each joined
// with a riding clip of the same duration and phase (model/riding_clip.h) when the rider's joints are
// named as the built-in soldier's; otherwise the rider keeps its rest pose, and a note says so. The
// rider's own clips are not used. Throws gpu::Error (InvalidArgument) naming the mount and the joint
// when the mount has no `saddleJoint`, and when the two together have more than MAX_MODEL_MATERIALS
// materials. When both have a base-colour texture, the mount's is kept and the rider's materials lose
// theirs (a model has one), with a note.
SkinnedModel mountRider(const SkinnedModel& mount, const SkinnedModel& rider, const std::string& saddleJoint,
                        std::string name, std::vector<std::string>* notes);

// The built-in cavalryman: the soldier (this seed) on the horse (this seed), named "cavalry".
SkinnedModel makeCavalry(std::uint32_t seed = 1);

}  // namespace model
