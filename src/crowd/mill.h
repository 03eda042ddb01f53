#pragma once
// Milling, as episodes (crowd/mill_schedule.h: when they start, and from where). In episode k a
// character stands at target k a moment, sets off to target k + 1 walking or running, changes gait now
// and then on a long way, and lands exactly on target k + 1 (crowd/arrival.h), facing and at the phase
// episode k + 1 starts with, standing there until it starts. A model that stands by holding its walk
// still (crowd/standing.h) walks its way bent, or gallops and walks the last of it bent.
#include <cstdint>

#include "crowd/behaviours.h"
#include "crowd/mill_schedule.h"

namespace crowd {

// Episode k's first state, and its first segment (standing there until the agent sets off).
Segment enterMillEpisode(Agent& agent, std::uint32_t episode, const PlanContext& context);
// The next segment of a milling character (agent.due has come).
Segment planMill(Agent& agent, const Segment& current, const PlanContext& context);

}  // namespace crowd
