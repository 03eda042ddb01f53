#pragma once
// How a character stands still: its model's standing clip at its natural rate or, for a model without
// one (the horse), its walk held at one point of the cycle (rate 0: a halt, not a walk on the spot).
// A stop can end exactly at a chosen phase, so a behaviour can hand over to a state it computed in
// closed form (crowd/mill.h, crowd/march.h): a standing clip reaches that phase by playing a little
// faster or slower while the character stands, a held walk by slowing to its halt over a longer or
// shorter time.
#include <cstdint>
#include <optional>

#include "crowd/behaviours.h"

namespace crowd {

// The clip a character stands with: the standing clip, else the walk (held still).
std::uint32_t standingClip(const PlanContext& context);
bool holdsWalkStill(const PlanContext& context);

// Standing at `position`, facing `heading`, at `phase` of the standing clip, from `start` on.
Segment standing(glm::vec3 position, float heading, float phase, double start, const PlanContext& context);

// Where a stop to standing is aimed: the heading it turns to, and the phase it must have at `until`.
struct StopAim {
    float heading = 0.0f;
    float phase = 0.0f;
    double until = 0.0;
};

// Stops `current` at `at`, crossfading (or slowing) to standing and turning to aim.heading, so that at
// aim.until it stands at aim.phase plus `cycles` whole cycles, counted from the phase origin of
// `current` (so that the count means the same wherever in `current` the stop starts: a solve that
// moves `at` keeps to one count). A standing clip plays them at whatever steady rate lands there, a
// held walk slows over whatever time does. Empty `cycles` is set to the count that keeps the standing
// clip nearest its natural rate (a held walk: the shortest slowing of at least kStopFade).
Segment stopAt(const Segment& current, double at, const StopAim& aim, std::optional<double>& cycles,
               const PlanContext& context);

// The longest a stop takes to come to a standstill (its crossfade or its slowing).
float longestStop(const PlanContext& context);

}  // namespace crowd
