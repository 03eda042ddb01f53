#pragma once
// Bakes a looping clip from a pose function, and the small helpers the characters' gaits share.
#include <functional>
#include <span>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "anim/clip.h"
#include "anim/skeleton.h"
#include "anim/transform.h"
#include "model/skinned_model.h"

namespace model {

// Writes a character's local transforms at `phase` in [0, 1); `pose` arrives holding the rest pose.
using PoseAtPhase = std::function<void(float phase, std::span<anim::Transform> pose)>;

// Samples `pose` at keyIntervals + 1 evenly spaced keys (the last a copy of the first, so the loop
// is seamless) into linear channels, one per joint and path that moves away from the rest pose.
anim::Clip bakeLoopingClip(std::string name, float duration, int keyIntervals, const anim::Skeleton& skeleton,
                           const PoseAtPhase& pose);

// The lowest y of the model's vertices skinned with these local transforms. Gaits lower or raise
// the root by it so that the feet, whatever the legs do, meet the ground at y = 0.
float lowestSkinnedY(const SkinnedModel& model, std::span<const anim::Transform> pose);

// Rotations of a joint about the model axes, in degrees. Characters face +z with y up, so
// swing(+) carries a hanging limb's far end forward, lean(+) tips an upright chain forward,
// bank(+) carries a hanging limb's end to the left (+x), and turn(+) turns the front to the left.
glm::quat swing(float degrees);
glm::quat lean(float degrees);
glm::quat bank(float degrees);
glm::quat turn(float degrees);

// A smooth wave over the loop, so keyed values repeat exactly after one cycle.
float wave(float phase, float cycles = 1.0f, float offset = 0.0f);

// A smooth bump at `center` of the loop: 1 there, fading over about `width` either side and
// wrapping round the loop's end.
float bump(float phase, float center, float width);

// The phase wrapped into [0, 1).
float wrapPhase(float phase);

// Index of the joint with this name; the characters' clip code asks only for joints it made.
std::uint32_t findJoint(const anim::Skeleton& skeleton, const std::string& name);

}  // namespace model
