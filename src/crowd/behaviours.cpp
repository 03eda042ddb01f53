#include "crowd/behaviours.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "crowd/motion.h"

namespace crowd {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kTurnRate = 2.5f;        // rad/s: a brisk but natural turn towards a target
constexpr float kAboutTurnSeconds = 2.5f;  // a formation's 180-degree turn, walking
constexpr float kStartFade = 0.4f, kGaitFade = 0.5f, kStopFade = 0.5f;

// A uniform number in [0, 1) from (seed, character, plan, salt): the same on every machine.
float unit(const Agent& agent, const PlanContext& context, std::uint32_t salt) {
    std::uint32_t h = context.settings.seed * 0x9E3779B9u ^ context.character * 0x85EBCA6Bu ^ agent.plans * 0xC2B2AE35u ^
                      salt * 0x27D4EB2Fu;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return static_cast<float>(h >> 8) / 16777216.0f;
}

float wrapAngle(float angle) { return angle - 2.0f * kPi * std::floor((angle + kPi) / (2.0f * kPi)); }

glm::vec2 groundOf(const MotionState& state) { return {state.position.x, state.position.z}; }

// A milling character's next trip (a commanded one's: the target and gait it was given): the segment
// that sets off, turning towards the target.
gpu::MotionRecord setOff(Agent& agent, const gpu::MotionRecord& current, const PlanContext& context) {
    if (!agent.commanded) {
        const float angle = 2.0f * kPi * unit(agent, context, 1);
        const float reach = context.settings.millRadius * std::sqrt(unit(agent, context, 2));
        agent.target = agent.home + reach * glm::vec2(std::cos(angle), std::sin(angle));
        const bool run = context.gaits.run != Gaits::kNone && unit(agent, context, 3) < 0.25f;
        agent.gait = run ? context.gaits.run : context.gaits.walk;
        agent.rate = 0.85f + 0.3f * unit(agent, context, 4);
    }
    const auto gait = static_cast<std::uint32_t>(agent.gait);
    gpu::MotionRecord next = transition(current, agent.due, gait, agent.rate, kStartFade, context);
    const MotionState here = evaluateMotion(current, agent.due, context.library, context.model);
    turnTowards(next, headingTowards(groundOf(here), agent.target, gait, context), kTurnRate);
    agent.stage = Agent::Stage::Cruise;
    agent.due += std::max(next.timing.y, next.timing.w);
    return next;
}

gpu::MotionRecord cruise(Agent& agent, const gpu::MotionRecord& current, const PlanContext& context) {
    const MotionState here = evaluateMotion(current, agent.due, context.library, context.model);
    const std::uint32_t gait = current.clips.y;
    const float speed = glm::length(context.library.stride(context.model, gait)) * current.phase.z;
    const float stopping = 0.5f * kStopFade * speed;
    const float remaining = glm::distance(groundOf(here), agent.target);
    if (remaining <= stopping + 0.25f) {
        // A commanded character stops for good; one without a standing clip keeps its gait in place.
        if (context.gaits.stand == Gaits::kNone && !agent.commanded) return setOff(agent, current, context);
        const std::uint32_t still = static_cast<std::uint32_t>(context.gaits.stand != Gaits::kNone ? context.gaits.stand : gait);
        gpu::MotionRecord stop = transition(current, agent.due, still, 1.0f, kStopFade, context);
        if (agent.commanded) {
            agent.stage = Agent::Stage::Forever;
            agent.due = Agent::kNever;
            if (context.gaits.stand == Gaits::kNone) stop.phase.w = 0.0f;
            return stop;
        }
        agent.stage = Agent::Stage::Stand;
        agent.due += kStopFade + 1.5f + 3.0f * unit(agent, context, 5);
        return stop;
    }
    // Now and then, on a long way, speed up to a run or slow down to a walk.
    std::uint32_t next = gait;
    if (!agent.commanded && context.gaits.run != Gaits::kNone && remaining > 4.0f && unit(agent, context, 6) < 0.3f)
        next = static_cast<std::uint32_t>(gait == static_cast<std::uint32_t>(context.gaits.run) ? context.gaits.walk
                                                                                                  : context.gaits.run);
    const float fade = next == gait ? 0.0f : kGaitFade;
    gpu::MotionRecord leg = transition(current, agent.due, next, agent.rate, fade, context);
    turnTowards(leg, headingTowards(groundOf(here), agent.target, next, context), kTurnRate);
    const float length = std::min(remaining - stopping, 3.0f + 4.0f * unit(agent, context, 7));
    agent.due += std::max({timeToCover(leg, length, context), leg.timing.y, leg.timing.w});
    return leg;
}

gpu::MotionRecord march(Agent& agent, const gpu::MotionRecord& current, const PlanContext& context) {
    const auto walk = static_cast<std::uint32_t>(context.gaits.walk);
    using Stage = Agent::Stage;
    switch (agent.stage) {
        case Stage::MarchOut:
        case Stage::MarchBack: {
            gpu::MotionRecord leg = transition(current, agent.due, walk, 1.0f, current.clips.y == walk ? 0.0f : kGaitFade, context);
            agent.stage = agent.stage == Stage::MarchOut ? Stage::TurnAbout : Stage::TurnHome;
            agent.due += timeToCover(leg, context.settings.marchLength, context);
            return leg;
        }
        case Stage::TurnAbout:
        case Stage::TurnHome: {
            // Both about-turns go the same way round: the second semicircle undoes the first's sideways
            // step, so the formation comes home to where it started.
            gpu::MotionRecord turn = transition(current, agent.due, walk, 1.0f, 0.0f, context);
            turn.timing.z = kPi / kAboutTurnSeconds;
            turn.timing.w = kAboutTurnSeconds;
            const bool halts = agent.stage == Stage::TurnHome && context.gaits.stand != Gaits::kNone;
            agent.stage = agent.stage == Stage::TurnAbout ? Stage::MarchBack : (halts ? Stage::Halt : Stage::MarchOut);
            agent.due += kAboutTurnSeconds;
            return turn;
        }
        case Stage::Halt:
        default: {
            gpu::MotionRecord halt =
                transition(current, agent.due, static_cast<std::uint32_t>(context.gaits.stand), 1.0f, kStopFade, context);
            agent.stage = Stage::MarchOut;
            agent.due += kStopFade + 3.0f;
            return halt;
        }
    }
}

}  // namespace

const char* behaviourName(Behaviour behaviour) {
    switch (behaviour) {
        case Behaviour::InPlace: return "in-place";
        case Behaviour::March: return "march";
        case Behaviour::Mill: return "mill";
    }
    return "?";
}

bool parseBehaviour(const std::string& name, Behaviour& behaviour) {
    for (Behaviour b : {Behaviour::InPlace, Behaviour::March, Behaviour::Mill})
        if (name == behaviourName(b)) return behaviour = b, true;
    return false;
}

gpu::MotionRecord transition(const gpu::MotionRecord& current, float start, std::uint32_t clip, float rate, float fade,
                             const PlanContext& context) {
    const MotionState state = evaluateMotion(current, start, context.library, context.model);
    gpu::MotionRecord next{};
    next.origin = glm::vec4(state.position, wrapAngle(state.heading));
    next.timing = glm::vec4(start, state.clipTo == clip ? 0.0f : fade, 0.0f, 0.0f);
    // Only the point in the cycle matters to the clips; dropping whole cycles keeps the numbers small.
    const float phase = state.phase - std::floor(state.phase);
    next.phase = glm::vec4(phase, current.phase.z, cyclesPerSecond(context.library, context.model, clip, rate), 1.0f);
    next.clips = glm::uvec4(state.clipTo, clip, 0u, 0u);
    return next;
}

void turnTowards(gpu::MotionRecord& segment, float heading, float turnRate) {
    const float delta = wrapAngle(heading - segment.origin.w);
    if (std::abs(delta) < 1e-4f) return;
    segment.timing.w = std::abs(delta) / turnRate;
    segment.timing.z = delta / segment.timing.w;
}

float headingTowards(const glm::vec2& from, const glm::vec2& target, std::uint32_t clip, const PlanContext& context) {
    const glm::vec2 way = target - from;
    const glm::vec2 stride = context.library.stride(context.model, clip);
    // turnToWorld turns model +z to (sin h, cos h): the heading that turns the stride onto the way.
    return std::atan2(way.x, way.y) - std::atan2(stride.x, stride.y);
}

float timeToCover(const gpu::MotionRecord& planned, float distance, const PlanContext& context) {
    gpu::MotionRecord segment = planned;  // still being planned: sealed here to be evaluated
    sealSegment(segment, context.library, context.model);
    const glm::vec2 origin(segment.origin.x, segment.origin.z);
    auto reached = [&](float elapsed) {
        const MotionState s = evaluateMotion(segment, segment.timing.x + elapsed, context.library, context.model);
        return glm::distance(groundOf(s), origin) >= distance;
    };
    float low = 0.0f, high = 1.0f;
    while (!reached(high)) {
        low = high;
        high *= 2.0f;
        if (high > 600.0f) return high;  // a gait too slow to get there: try again later
    }
    for (int i = 0; i < 24; ++i) {
        const float middle = 0.5f * (low + high);
        (reached(middle) ? high : low) = middle;
    }
    return high;
}

gpu::MotionRecord startBehaviour(Agent& agent, const gpu::MotionRecord& first, const PlanContext& context) {
    agent.kind = context.settings.kind;
    agent.home = glm::vec2(first.origin.x, first.origin.z);
    if (agent.kind == Behaviour::InPlace || !context.gaits.canTravel()) {
        agent.stage = Agent::Stage::Forever;
        agent.due = Agent::kNever;
        return first;
    }
    const bool stands = context.gaits.stand != Gaits::kNone;
    const std::uint32_t clip = static_cast<std::uint32_t>(stands ? context.gaits.stand : context.gaits.walk);
    if (agent.kind == Behaviour::March) {
        // In step: every member of the formation starts at the same phase and keeps the same rate.
        agent.stage = Agent::Stage::MarchOut;
        agent.due = stands ? 1.0f : 0.0f;
        return inPlaceSegment(context.library, context.model, clip, glm::vec3(first.origin), first.origin.w, 0.0f,
                              0.0f, 1.0f);
    }
    agent.stage = Agent::Stage::Stand;
    agent.due = stands ? 3.0f * unit(agent, context, 0) : 0.0f;
    gpu::MotionRecord standing = inPlaceSegment(context.library, context.model, clip, glm::vec3(first.origin),
                                                first.origin.w, 0.0f, first.phase.x, 1.0f);
    standing.phase.w = 1.0f;
    return standing;
}

gpu::MotionRecord planNext(Agent& agent, const gpu::MotionRecord& current, const PlanContext& context) {
    gpu::MotionRecord next;
    if (agent.stage == Agent::Stage::Play) {
        // A commanded clip: crossfade to it and keep it, carried by its root motion.
        next = transition(current, agent.due, static_cast<std::uint32_t>(agent.gait), agent.rate, agent.fade, context);
        agent.stage = Agent::Stage::Forever;
        agent.due = Agent::kNever;
    } else if (agent.kind == Behaviour::March && !agent.commanded) {
        next = march(agent, current, context);
    } else if (agent.stage == Agent::Stage::Stand || agent.stage == Agent::Stage::Forever) {
        next = setOff(agent, current, context);
    } else {
        next = cruise(agent, current, context);
    }
    ++agent.plans;
    return next;
}

}  // namespace crowd
