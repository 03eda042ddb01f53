#include "crowd/standing.h"

#include <algorithm>
#include <cmath>

#include "crowd/plan_steps.h"

namespace crowd {
namespace {

// A standing clip: plays at whatever rate puts it at `phase` (in its own cycles) at aim.until.
void landOnPhaseByRate(Segment& stop, double phase, const StopAim& aim) {
    gpu::MotionRecord& m = stop.motion;
    const double fade = m.timing.y, from = m.phase.y;
    // Phase at `until`: start + fade x (from + to) / 2 + to x (span - fade) = lead + to x effective.
    const double lead = m.phase.x + 0.5 * from * fade;
    const double effective = std::max(aim.until - stop.start - 0.5 * fade, 1e-3);
    stop.rate = (phase - lead) / effective;
    m.phase.z = static_cast<float>(stop.rate);
}

// A held walk: slows from its rate to 0 over whatever time ends it at `phase` (in its own cycles).
void landOnPhaseBySlowing(Segment& stop, double phase) {
    gpu::MotionRecord& m = stop.motion;
    const double from = m.phase.y;
    // Slowing linearly to 0 over f seconds adds from x f / 2 cycles.
    if (from > 0.0) m.timing.y = static_cast<float>(2.0 * (phase - m.phase.x) / from);
}

// The whole cycles that keep a standing clip nearest its natural rate, or a held walk's slowing
// shortest but at least kStopFade: counted, as the stop's own phase is, from its start's whole cycle.
double naturalCycles(const Segment& stop, const StopAim& aim, bool held) {
    const gpu::MotionRecord& m = stop.motion;
    if (held) return std::ceil(m.phase.x + 0.5 * m.phase.y * kStopFade - aim.phase);
    const double fade = m.timing.y;
    const double lead = m.phase.x + 0.5 * m.phase.y * fade;
    return std::round(lead + m.phase.z * (aim.until - stop.start - 0.5 * fade) - aim.phase);
}

}  // namespace

std::uint32_t standingClip(const PlanContext& context) {
    return static_cast<std::uint32_t>(holdsWalkStill(context) ? context.gaits.walk : context.gaits.stand);
}

bool holdsWalkStill(const PlanContext& context) { return context.gaits.stand == Gaits::kNone; }

Segment standing(glm::vec3 position, float heading, float phase, double start, const PlanContext& context) {
    const float rate = holdsWalkStill(context) ? 0.0f : 1.0f;
    Segment s{start,
              inPlaceSegment(context.library, context.model, standingClip(context), position, heading, 0.0f, phase, rate),
              exactCyclesPerSecond(context.library, context.model, standingClip(context), rate)};
    // Carried by root motion like every planned segment: a standing clip's sway moves the body with it.
    s.motion.phase.w = 1.0f;
    return s;
}

Segment stopAt(const Segment& current, double at, const StopAim& aim, std::optional<double>& cycles,
               const PlanContext& context) {
    const bool held = holdsWalkStill(context);
    Segment stop = transition(current, at, standingClip(context), held ? 0.0f : 1.0f, kStopFade, context);
    // The whole cycles of `current` the transition dropped from the stop's phase.
    const double dropped = std::round(unwrappedPhase(current, at) - stop.motion.phase.x);
    if (!cycles) cycles = naturalCycles(stop, aim, held) + dropped;
    const double phase = aim.phase + *cycles - dropped;
    if (held) landOnPhaseBySlowing(stop, phase);
    else landOnPhaseByRate(stop, phase, aim);
    turnTowards(stop.motion, aim.heading, kTurnRate);
    seal(stop, context.library, context.model);
    return stop;
}

float longestStop(const PlanContext& context) {
    if (!holdsWalkStill(context)) return kStopFade;
    // Up to one more whole cycle of the walk, slowing from its slowest rate.
    const float cycles = cyclesPerSecond(context.library, context.model, standingClip(context), kSlowestGaitRate);
    return cycles > 0.0f ? kStopFade + 2.0f / cycles : kStopFade;
}

}  // namespace crowd
