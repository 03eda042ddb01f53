#include "crowd/commands.h"

#include <algorithm>
#include <cmath>

#include "crowd/plan_steps.h"

namespace crowd {
namespace {

enum Salt : std::uint32_t { kLength = 7 };

Segment setOff(Agent& agent, const Segment& current, const PlanContext& context) {
    const auto gait = static_cast<std::uint32_t>(agent.gait);
    Segment next = transition(current, agent.due, gait, agent.rate, kStartFade, context);
    const MotionState here = stateOf(current, agent.due, context.library, context.model);
    turnTowards(next.motion, headingTowards(groundOf(here), agent.target, gait, context), kTurnRate);
    agent.stage = Agent::Stage::Cruise;
    agent.due += std::max(next.motion.timing.y, next.motion.timing.w);
    return next;
}

Segment cruise(Agent& agent, const Segment& current, const PlanContext& context) {
    const MotionState here = stateOf(current, agent.due, context.library, context.model);
    const std::uint32_t gait = current.motion.clips.y;
    const float speed = glm::length(context.library.stride(context.model, gait)) * current.motion.phase.z;
    const float stopping = 0.5f * kStopFade * speed;
    const float remaining = glm::distance(groundOf(here), agent.target);
    if (remaining <= stopping + 0.25f) {
        // It stops for good: with its standing clip, or (a model without one) its gait on the spot.
        const bool stands = context.gaits.stand != Gaits::kNone;
        const std::uint32_t still = static_cast<std::uint32_t>(stands ? context.gaits.stand : gait);
        Segment stop = transition(current, agent.due, still, stands ? 1.0f : agent.rate, kStopFade, context);
        if (!stands) stop.motion.phase.w = 0.0f;
        agent.stage = Agent::Stage::Forever;
        agent.due = Agent::kNever;
        return stop;
    }
    Segment leg = transition(current, agent.due, gait, agent.rate, 0.0f, context);
    turnTowards(leg.motion, headingTowards(groundOf(here), agent.target, gait, context), kTurnRate);
    const float length = std::min(remaining - stopping, 3.0f + 4.0f * unit(agent, context, kLength));
    agent.due += std::max({timeToCover(leg, length, context), leg.motion.timing.y, leg.motion.timing.w});
    return leg;
}

// A commanded clip: crossfade to it and keep it, carried by its root motion.
Segment play(Agent& agent, const Segment& current, const PlanContext& context) {
    Segment next = transition(current, agent.due, static_cast<std::uint32_t>(agent.gait), agent.rate, agent.fade, context);
    agent.stage = Agent::Stage::Forever;
    agent.due = Agent::kNever;
    return next;
}

}  // namespace

Segment planCommand(Agent& agent, const Segment& current, const PlanContext& context) {
    switch (agent.stage) {
        case Agent::Stage::Play: return play(agent, current, context);
        case Agent::Stage::Cruise: return cruise(agent, current, context);
        default: return setOff(agent, current, context);
    }
}

}  // namespace crowd
