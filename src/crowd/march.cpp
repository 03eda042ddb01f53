#include "crowd/march.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "crowd/arrival.h"
#include "crowd/plan_steps.h"
#include "crowd/standing.h"

namespace crowd {
namespace {

constexpr float kAboutTurnSeconds = 2.5f;  // a formation's 180-degree turn, walking
constexpr double kPrologue = 1.0;          // seconds the formation stands before its first cycle
constexpr float kHaltRest = 3.0f;          // seconds it stands, at least, after each halt
constexpr float kCyclePhase = 0.0f;        // of the standing clip, at every cycle's start

double cycleStart(std::uint32_t cycle, const PlanContext& context) {
    return kPrologue + static_cast<double>(cycle) * context.rhythm.marchCycle;
}

std::uint32_t walkOf(const PlanContext& context) { return static_cast<std::uint32_t>(context.gaits.walk); }

// Turning about (half a circle in kAboutTurnSeconds) while walking on.
Segment aboutTurn(const Segment& current, double at, const PlanContext& context) {
    Segment turn = transition(current, at, walkOf(context), 1.0f, 0.0f, context);
    turn.motion.timing.z = kPi / kAboutTurnSeconds;
    turn.motion.timing.w = kAboutTurnSeconds;
    seal(turn, context.library, context.model);
    return turn;
}

// The whole cycles of `leg` before `next` (planned from it) starts its own count.
double cyclesBefore(const Segment& leg, const Segment& next) {
    return std::round(unwrappedPhase(leg, next.start) - next.motion.phase.x);
}

StopAim haltAim(const Agent& agent) { return {agent.homeHeading, kCyclePhase, agent.episodeEnd}; }

Segment marchOut(Agent& agent, const Segment& current, const PlanContext& context) {
    Segment leg = transition(current, agent.due, walkOf(context), 1.0f, kGaitFade, context);
    agent.stage = Agent::Stage::TurnAbout;
    agent.due += context.rhythm.marchLeg;  // the same for every member: the formation stays in step
    return leg;
}

Segment turnAbout(Agent& agent, const Segment& current, const PlanContext& context) {
    agent.stage = Agent::Stage::MarchBack;
    const double at = agent.due;
    agent.due += kAboutTurnSeconds;
    return aboutTurn(current, at, context);
}

// The leg back, solved so that after turning about and halting the member stands where it started.
Segment marchBack(Agent& agent, const Segment& current, const PlanContext& context) {
    const StopAim aim = haltAim(agent);
    // The halt's whole cycles, counted from the leg's phase origin: the turn between starts a cycle of
    // its own wherever the leg ends, so its count is converted both ways.
    std::optional<double> cycles;
    const ArrivalTail tail = [&](const Segment& leg, double legEnd) {
        const Segment turn = aboutTurn(leg, legEnd, context);
        const double beforeTurn = cyclesBefore(leg, turn);
        std::optional<double> turnCycles;
        if (cycles) turnCycles = *cycles - beforeTurn;
        const Segment halt = stopAt(turn, legEnd + kAboutTurnSeconds, aim, turnCycles, context);
        if (!cycles) cycles = *turnCycles + beforeTurn;
        return halt;
    };
    const Arrival arrival = arrive(current, {agent.due, walkOf(context), 1.0f, 0.0f},
                                   glm::vec2(agent.home.x, agent.home.z), agent.episodeEnd, tail, context);
    agent.stopCycles = cycles.value_or(0.0) - cyclesBefore(arrival.leg, aboutTurn(arrival.leg, arrival.legEnd, context));
    agent.stage = Agent::Stage::TurnHome;
    agent.due = arrival.legEnd;
    return arrival.leg;
}

Segment turnHome(Agent& agent, const Segment& current, const PlanContext& context) {
    agent.stage = Agent::Stage::Halt;
    const double at = agent.due;
    agent.due += kAboutTurnSeconds;
    return aboutTurn(current, at, context);
}

Segment halt(Agent& agent, const Segment& current, const PlanContext& context) {
    const double at = agent.due;  // as the leg back planned it
    std::optional<double> cycles = agent.stopCycles;  // counted from the turn's phase origin
    agent.stage = Agent::Stage::Rest;
    agent.due = agent.episodeEnd;
    return stopAt(current, at, haltAim(agent), cycles, context);
}

}  // namespace

Segment startMarch(Agent& agent, const PlanContext& context) {
    // Standing until the first cycle, arriving at its phase then at the natural rate.
    const float rate = cyclesPerSecond(context.library, context.model, standingClip(context),
                                       holdsWalkStill(context) ? 0.0f : 1.0f);
    const double before = kCyclePhase - rate * kPrologue;
    const float phase = static_cast<float>(before - std::floor(before));
    agent.episode = 0;
    agent.plans = 0;
    agent.stage = Agent::Stage::MarchOut;
    agent.due = cycleStart(0, context);
    agent.episodeEnd = cycleStart(1, context);
    return standing(agent.home, agent.homeHeading, phase, 0.0, context);
}

Segment enterMarchCycle(Agent& agent, std::uint32_t cycle, const PlanContext& context) {
    agent.episode = cycle;
    agent.plans = 0;
    agent.stage = Agent::Stage::MarchOut;
    agent.due = cycleStart(cycle, context);
    agent.episodeEnd = cycleStart(cycle + 1, context);
    return standing(agent.home, agent.homeHeading, kCyclePhase, agent.due, context);
}

std::uint32_t marchCycleAt(double time, const PlanContext& context) {
    const double guess = std::floor((time - kPrologue) / context.rhythm.marchCycle);
    // Clamped (a NaN guess to 0) before it becomes an index, and the walk below stops at the last one.
    constexpr std::uint32_t kLast = 4000000000u;
    auto cycle = static_cast<std::uint32_t>(guess > 0.0 ? std::min(guess, static_cast<double>(kLast)) : 0.0);
    // The division may round across a boundary: settle on the cycle whose start is at or before `time`.
    while (cycle > 0 && cycleStart(cycle, context) > time) --cycle;
    while (cycle < kLast && cycleStart(cycle + 1, context) <= time) ++cycle;
    return cycle;
}

Segment planMarch(Agent& agent, const Segment& current, const PlanContext& context) {
    using Stage = Agent::Stage;
    switch (agent.stage) {
        case Stage::MarchOut: return marchOut(agent, current, context);
        case Stage::TurnAbout: return turnAbout(agent, current, context);
        case Stage::MarchBack: return marchBack(agent, current, context);
        case Stage::TurnHome: return turnHome(agent, current, context);
        case Stage::Halt: return halt(agent, current, context);
        case Stage::Rest:
        default: return enterMarchCycle(agent, agent.episode + 1, context);
    }
}

void measureMarch(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                  const BehaviourSettings& settings, Rhythm& rhythm) {
    // A provisional cycle long enough for anything: the halt's length is what is being measured.
    Rhythm provisional = rhythm;
    provisional.marchCycle = 1e4;
    const PlanContext measuring{library, model, gaits, settings, provisional, 0};
    Agent agent;
    Segment segment = enterMarchCycle(agent, 0, measuring);
    const Segment leg = transition(segment, agent.due, walkOf(measuring), 1.0f, kGaitFade, measuring);
    provisional.marchLeg = timeToCover(leg, settings.marchLength, measuring);
    // Out, about, back, about: then the halt.
    while (agent.stage != Agent::Stage::Halt) segment = planMarch(agent, segment, measuring);
    const double stopAt = agent.due;
    double haltLength = longestStop(measuring) + kHaltRest;
    if (!holdsWalkStill(measuring)) {
        // The standing clip's phase after the stop's crossfade at the natural rate, and the rest that
        // brings it to kCyclePhase: at least kHaltRest, less than one more cycle.
        const Segment stop = transition(segment, stopAt, standingClip(measuring), 1.0f, kStopFade, measuring);
        const double rate = stop.motion.phase.z, fade = stop.motion.timing.y;
        const double phaseThen = stop.motion.phase.x + 0.5 * (stop.motion.phase.y + rate) * fade + rate * kHaltRest;
        const double short_ = std::ceil(phaseThen - kCyclePhase) + kCyclePhase - phaseThen;
        haltLength = fade + kHaltRest + (rate > 0.0 ? short_ / rate : 0.0);
    }
    rhythm.marchLeg = provisional.marchLeg;
    rhythm.marchCycle = stopAt - cycleStart(0, measuring) + haltLength;
}

}  // namespace crowd
