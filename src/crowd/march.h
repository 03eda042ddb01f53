#pragma once
// Marching, as cycles. Every member of a formation starts each cycle at the same time from the same
// closed-form state: standing where it was laid out, facing the way it was laid out, at phase 0 of its
// standing clip. It marches out marchLength metres, turns about, marches back, turns about the same way
// (the second semicircle undoes the first's sideways step) and halts, landing exactly on its starting
// place and phase (crowd/arrival.h) when the next cycle starts. So the formation keeps its ground and
// its step over any number of cycles, and the cycle holding any time is found by a division.
#include <cstdint>

#include "crowd/behaviours.h"

namespace crowd {

// Before the first cycle: standing 1 s (the prologue), so a formation does not march off at once.
Segment startMarch(Agent& agent, const PlanContext& context);
// Cycle k's first state, and its first segment (standing there, due to march out at once).
Segment enterMarchCycle(Agent& agent, std::uint32_t cycle, const PlanContext& context);
// The cycle under way at `time` (0 before the first starts).
std::uint32_t marchCycleAt(double time, const PlanContext& context);
// The next segment of a marching character (agent.due has come).
Segment planMarch(Agent& agent, const Segment& current, const PlanContext& context);

// The seconds of a march out and of a whole cycle for this model: one member's cycle planned from a
// canonical start, its halt as long as it takes the standing clip to come back to phase 0 at its
// natural rate (at least kHaltRest after the stop), so that no member ever plays it faster or slower.
void measureMarch(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                  const BehaviourSettings& settings, Rhythm& rhythm);

}  // namespace crowd
