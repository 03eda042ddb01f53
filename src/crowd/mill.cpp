#include "crowd/mill.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "crowd/arrival.h"
#include "crowd/mill_schedule.h"
#include "crowd/plan_steps.h"
#include "crowd/standing.h"

namespace crowd {
namespace {

// Metres from the target within which the last leg is solved to land on it (crowd/arrival.h); legs
// before it aim at the target and cover 3 to 7 m.
constexpr float kFinalReach = 5.0f;
// Metres from the target where a galloping model that holds its walk still fades to the walk, and the
// shortest gallop before that.
constexpr float kWalkIn = 5.0f, kShortestGallop = 1.5f;
constexpr int kMostExtraCycles = 3;
enum Salt : std::uint32_t { kRun = 200, kRate, kSwitch, kLength };

glm::vec2 here(const Agent& agent, const Segment& current, const PlanContext& context) {
    return groundOf(stateOf(current, agent.due, context.library, context.model));
}

StopAim aimOf(const Agent& agent, const PlanContext& context) {
    const std::uint32_t next = agent.episode + 1;
    return {millHeading(agent, next, context), millPhase(agent, next, context), agent.episodeEnd};
}

// The last leg, solved to stand on the target at the next episode's start, its heading and phase.
Segment arriveStraight(Agent& agent, const Segment& current, const LegStart& start, const PlanContext& context) {
    const StopAim aim = aimOf(agent, context);
    std::optional<double> cycles;
    const ArrivalTail tail = [&](const Segment& leg, double legEnd) { return stopAt(leg, legEnd, aim, cycles, context); };
    const Arrival arrival = arrive(current, start, agent.target, agent.episodeEnd, tail, context);
    agent.stopCycles = cycles.value_or(0.0);
    agent.stage = Agent::Stage::Stop;
    agent.due = arrival.legEnd;
    return arrival.leg;
}

// A walk held still ends at the aimed phase, so the whole cycles the way takes fix its length: beyond
// the straight way, half a stride and the arc of the first turn, and up to one more stride, which two
// bent legs then take up. Should the turns still leave it short, one more cycle (or two) is walked.
Segment arriveBentWalk(Agent& agent, const Segment& current, const LegStart& start, const PlanContext& context) {
    const StopAim aim = aimOf(agent, context);
    const MotionState here = stateOf(current, start.at, context.library, context.model);
    const double stride = glm::length(context.library.stride(context.model, start.gait));
    const double rate = cyclesPerSecond(context.library, context.model, start.gait, start.rate);
    const float turn = std::abs(wrapAngle(headingTowards(groundOf(here), agent.target, start.gait, context) - here.heading));
    const double arc = stride * rate / kTurnRate * turn;  // metres walked turning towards the target
    const double way = (glm::distance(groundOf(here), agent.target) + arc) / stride + 0.5;
    const double phase = here.phase - std::floor(here.phase);
    const double fadeExtra = 0.5 * (current.motion.phase.z - rate) * start.fade;
    BentArrival arrival;
    std::optional<double> cycles;
    for (int extra = 0; extra < kMostExtraCycles; ++extra) {
        const double whole = std::ceil(phase + way - aim.phase) + extra;
        // Cycles walked before the stop: all but what the leg's fade adds and the stop's, which slows
        // over half a cycle more than the shortest stop, so that whatever the turns it chooses `whole`.
        const double walked = aim.phase + whole - phase - (0.5 * rate * kStopFade + 0.5) - fadeExtra;
        const double length = std::max(walked / rate, 2.0 * start.fade);
        cycles.reset();
        const ArrivalTail tail = [&](const Segment& leg, double legEnd) { return stopAt(leg, legEnd, aim, cycles, context); };
        const auto stopReach = static_cast<float>(stride * (0.5 * rate * kStopFade + 0.5));
        arrival = arriveBent(current, start, length, stopReach, agent.target, agent.episodeEnd, tail, context);
        if (arrival.miss < kArrivalTolerance) break;
    }
    agent.stopCycles = cycles.value_or(0.0);
    agent.bendTurn = arrival.secondTurn;
    agent.bendLength = arrival.secondLength;
    agent.stage = Agent::Stage::Bend;
    agent.due = arrival.firstEnd;
    return arrival.first;
}

// The second leg of a bent arrival, as arriveBent planned it.
Segment bend(Agent& agent, const Segment& current, const PlanContext& context) {
    const Segment leg = legTurningBy(current, {agent.due, current.motion.clips.y, agent.rate, 0.0f}, agent.bendTurn,
                                     context);
    agent.stage = Agent::Stage::Stop;
    agent.due += agent.bendLength;
    return leg;
}

// A leg towards the target in `gait`, for as long as its turn and fade take.
Segment headFor(Agent& agent, const Segment& current, std::uint32_t gait, float fade, const PlanContext& context) {
    const glm::vec2 from = here(agent, current, context);
    Segment leg = transition(current, agent.due, gait, agent.rate, fade, context);
    turnTowards(leg.motion, headingTowards(from, agent.target, gait, context), kTurnRate);
    agent.stage = Agent::Stage::Cruise;
    agent.due += std::max(leg.motion.timing.y, leg.motion.timing.w);
    return leg;
}

// A model that holds its walk still: a walk goes all the way bent (crowd/arrival.h), so the bend is
// spread over the whole trip; a gallop keeps on to kWalkIn from the target, then the bent legs fade
// from it to the walk.
Segment setOffHolding(Agent& agent, const Segment& current, float way, const PlanContext& context) {
    const bool gallop =
        context.gaits.run != Gaits::kNone && way > kWalkIn + kShortestGallop && unit(agent, context, kRun) < 0.3f;
    agent.gait = gallop ? context.gaits.run : context.gaits.walk;
    const auto gait = static_cast<std::uint32_t>(agent.gait);
    if (!gallop) return arriveBentWalk(agent, current, {agent.due, gait, agent.rate, kStartFade}, context);
    return headFor(agent, current, gait, kStartFade, context);
}

Segment cruiseHolding(Agent& agent, const Segment& current, float remaining, const PlanContext& context) {
    const std::uint32_t gait = current.motion.clips.y;
    const auto walk = static_cast<std::uint32_t>(context.gaits.walk);
    if (gait == walk) return arriveBentWalk(agent, current, {agent.due, walk, agent.rate, 0.0f}, context);
    if (remaining <= kWalkIn) return arriveBentWalk(agent, current, {agent.due, walk, agent.rate, kGaitFade}, context);
    Segment leg = headFor(agent, current, gait, 0.0f, context);
    const float length = std::min(3.0f + 4.0f * unit(agent, context, kLength), remaining - 0.5f * kWalkIn);
    agent.due = std::max(agent.due, leg.start + timeToCover(leg, length, context));
    return leg;
}

Segment setOff(Agent& agent, const Segment& current, const PlanContext& context) {
    const glm::vec2 from = here(agent, current, context);
    const float way = glm::distance(from, agent.target);
    agent.rate = kSlowestGaitRate + kGaitRateRange * unit(agent, context, kRate);
    if (holdsWalkStill(context)) return setOffHolding(agent, current, way, context);
    // Running only pays on a way longer than the last leg.
    const bool run = context.gaits.run != Gaits::kNone && way > kFinalReach && unit(agent, context, kRun) < 0.25f;
    agent.gait = run ? context.gaits.run : context.gaits.walk;
    const auto gait = static_cast<std::uint32_t>(agent.gait);
    if (way <= kFinalReach) return arriveStraight(agent, current, {agent.due, gait, agent.rate, kStartFade}, context);
    return headFor(agent, current, gait, kStartFade, context);
}

Segment cruise(Agent& agent, const Segment& current, const PlanContext& context) {
    const glm::vec2 from = here(agent, current, context);
    const std::uint32_t gait = current.motion.clips.y;
    const float remaining = glm::distance(from, agent.target);
    if (holdsWalkStill(context)) return cruiseHolding(agent, current, remaining, context);
    if (remaining <= kFinalReach) return arriveStraight(agent, current, {agent.due, gait, agent.rate, 0.0f}, context);
    // Now and then, on a long way, speed up to a run or slow down to a walk.
    std::uint32_t next = gait;
    if (context.gaits.run != Gaits::kNone && unit(agent, context, kSwitch) < 0.3f)
        next = static_cast<std::uint32_t>(gait == static_cast<std::uint32_t>(context.gaits.run) ? context.gaits.walk
                                                                                                  : context.gaits.run);
    Segment leg = transition(current, agent.due, next, agent.rate, next == gait ? 0.0f : kGaitFade, context);
    turnTowards(leg.motion, headingTowards(from, agent.target, next, context), kTurnRate);
    // Leave at least half the last leg's reach for it.
    const float length = std::min(3.0f + 4.0f * unit(agent, context, kLength), remaining - 0.5f * kFinalReach);
    agent.due += std::max({timeToCover(leg, length, context), leg.motion.timing.y, leg.motion.timing.w});
    return leg;
}

Segment stop(Agent& agent, const Segment& current, const PlanContext& context) {
    const StopAim aim = aimOf(agent, context);
    const double at = agent.due;  // where the arrival ended the leg: the stop it solved for
    std::optional<double> cycles = agent.stopCycles;  // as the arrival planned it
    agent.stage = Agent::Stage::Rest;
    agent.due = agent.episodeEnd;
    return stopAt(current, at, aim, cycles, context);
}

}  // namespace

Segment enterMillEpisode(Agent& agent, std::uint32_t episode, const PlanContext& context) {
    agent.episode = episode;
    agent.plans = 0;
    agent.stage = Agent::Stage::Stand;
    agent.episodeEnd = millEpisodeStart(episode + 1, context);
    agent.target = millTarget(agent, episode + 1, context);
    const double start = millEpisodeStart(episode, context);
    agent.due = start + millWait(episode, context);
    const glm::vec2 place = millTarget(agent, episode, context);
    return standing(glm::vec3(place.x, agent.home.y, place.y), millHeading(agent, episode, context),
                    millPhase(agent, episode, context), start, context);
}

Segment planMill(Agent& agent, const Segment& current, const PlanContext& context) {
    switch (agent.stage) {
        case Agent::Stage::Stand: return setOff(agent, current, context);
        case Agent::Stage::Cruise: return cruise(agent, current, context);
        case Agent::Stage::Bend: return bend(agent, current, context);
        case Agent::Stage::Stop: return stop(agent, current, context);
        case Agent::Stage::Rest:
        default: return enterMillEpisode(agent, agent.episode + 1, context);
    }
}

}  // namespace crowd
