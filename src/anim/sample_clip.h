#pragma once
// Sampling job: a clip at a time, over a rest pose, gives every joint's local transform.
#include <span>

#include "anim/clip.h"
#include "anim/transform.h"

namespace anim {

// Writes the local transform of every joint at `time` seconds into `out` (same size as `rest`).
// Joints or paths the clip does not animate keep their rest value. Time wraps into
// [0, duration) so clips loop; a clip of zero duration samples its first key.
// Rotations are interpolated along the shorter arc and normalized. Allocates nothing.
void sampleClip(const Clip& clip, float time, std::span<const Transform> rest, std::span<Transform> out);

// Wraps a time into [0, duration); zero or negative durations give 0.
float wrapTime(float time, float duration);

}  // namespace anim
