#pragma once
// How far a clip can move a skinned vertex from the model's origin, bounded from its keys alone, so
// that no time the clip is ever sampled at (between keys, past CUBICSPLINE overshoots) can escape the
// bound. The glTF loader refuses clips whose bound leaves the range where float skinning and shading
// stay finite: finite keys near the float limit would otherwise animate into inf and NaN.
#include <span>

#include "anim/clip.h"
#include "anim/skeleton.h"

namespace anim {

// The largest magnitude a channel's sampled value can have at any time: the length of a translation
// or of a rotation before it is normalized, the largest |component| of a scale. For CUBICSPLINE, the
// Hermite basis on [0, 1] keeps the key values' weights in [0, 1] and the tangents' within 4/27.
double channelReach(const Channel& channel);

struct PoseReach {
    // Bound on the distance of every skinned vertex from the origin, and on the growth of the bone
    // matrices' linear part (times max(1, maxBindDistance)), over every pose of the clip.
    double distance = 0.0;
    // When the bound exceeds the limit: the first channel with which it does (taking the clip's
    // channels in order), or -1 when the rest pose alone does. -1 when within the limit.
    int channel = -1;
};

// `maxBindDistance`: the largest |position| of a bind-pose vertex. Bounds are products of norms down
// the hierarchy (a scale's largest component, the spectral norm of the root transform and inverse
// bind matrices), so they are tight for one joint and generous for deep chains, where each joint's
// largest translation and scale may come at different times; real characters stay many orders of
// magnitude below any useful limit. O(keys + joints), and O(joints x channels) more when over it.
PoseReach poseReach(const Skeleton& skeleton, const Clip& clip, double maxBindDistance, double limit);

}  // namespace anim
