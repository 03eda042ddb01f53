#pragma once
// Which events of two clips are one event in a crossfade (docs/events.md#firing): a walk's and a run's
// footstep of the same foot. A pair fires once, where the phase meets the point blended by the
// crossfade's weight, instead of each clip firing its own while it weighs more (which can lose a step
// when the two points straddle the fade's half-way moment).
//
// Two events pair when they have the same name and joint and each is the only one of that name and
// joint in its clip (a clip with two steps of one foot a cycle has no single partner to blend with:
// its events keep the larger-weight rule).
#include <cstdint>
#include <vector>

#include "anim/clip.h"

namespace crowd {

// The event of `from` that event `toEvent` of `to` pairs with, or -1.
std::int32_t pairedEvent(const anim::Clip& from, const anim::Clip& to, std::uint32_t toEvent);
// Whether event `fromEvent` of `from` pairs with one of `to`.
bool hasPartner(const anim::Clip& from, std::uint32_t fromEvent, const anim::Clip& to);

// For the GPU's tables: per clip, per event, a key equal for events of one name and joint across the
// clips (pairable ones only), or -1 for an event with another of its name and joint in its clip. Two
// events of two clips pair exactly when their keys are equal and not -1 (pairedEvent's rule).
std::vector<std::vector<std::int32_t>> eventPairKeys(const std::vector<anim::Clip>& clips);

// Where a pair fires in the cycle: the from-clip's point `base` (taken within half a cycle of the
// to-clip's) moving by `drift` cycles to the to-clip's point as the weight rises from 0 to 1.
struct BlendedPoint {
    double base, drift;
};
BlendedPoint blendedPoint(double fromPoint, double toPoint);

}  // namespace crowd
