#include "crowd/plan_steps.h"

#include <algorithm>
#include <cmath>

namespace crowd {

float unit(const PlanContext& context, std::uint32_t episode, std::uint32_t plan, std::uint32_t salt) {
    std::uint32_t h = context.settings.seed * 0x9E3779B9u ^ context.character * 0x85EBCA6Bu ^ plan * 0xC2B2AE35u ^
                      salt * 0x27D4EB2Fu;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= episode * 0x165667B1u;  // after a first round, so episode 0 keeps the choices of one hash round
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return static_cast<float>(h >> 8) / 16777216.0f;
}

float unit(const Agent& agent, const PlanContext& context, std::uint32_t salt) {
    return unit(context, agent.episode, agent.plans, salt);
}

float wrapAngle(float angle) { return angle - 2.0f * kPi * std::floor((angle + kPi) / (2.0f * kPi)); }

glm::vec2 groundOf(const MotionState& state) { return {state.position.x, state.position.z}; }

float headingAlong(glm::vec2 way) { return std::atan2(way.x, way.y); }

Segment transition(const Segment& current, double start, std::uint32_t clip, float rate, float fade,
                   const PlanContext& context) {
    const MotionState state = stateOf(current, start, context.library, context.model);
    const float cycles = cyclesPerSecond(context.library, context.model, clip, rate);
    const float from = current.motion.phase.z;
    const bool changes = state.clipTo != clip || from != cycles;
    Segment next{start, {}, exactCyclesPerSecond(context.library, context.model, clip, rate)};
    next.motion.origin = glm::vec4(state.position, wrapAngle(state.heading));
    next.motion.timing = glm::vec4(0.0f, changes ? fade : 0.0f, 0.0f, 0.0f);
    // Only the point in the cycle matters to the clips; dropping whole cycles keeps the numbers small.
    const float phase = state.phase - std::floor(state.phase);
    next.motion.phase = glm::vec4(phase, from, cycles, 1.0f);
    next.motion.clips = glm::uvec4(state.clipTo, clip, 0u, 0u);
    return next;
}

void turnTowards(gpu::MotionRecord& segment, float heading, float turnRate) {
    const float delta = wrapAngle(heading - segment.origin.w);
    if (std::abs(delta) < 1e-4f) return;
    turnBy(segment, delta, turnRate);
}

void turnBy(gpu::MotionRecord& segment, float angle, float turnRate) {
    segment.timing.w = std::abs(angle) / turnRate;
    segment.timing.z = segment.timing.w > 0.0f ? angle / segment.timing.w : 0.0f;
}

float headingTowards(const glm::vec2& from, const glm::vec2& target, std::uint32_t clip, const PlanContext& context) {
    const glm::vec2 stride = context.library.stride(context.model, clip);
    // turnToWorld turns model +z to (sin h, cos h): the heading that turns the stride onto the way.
    return headingAlong(target - from) - headingAlong(stride);
}

float timeToCover(const Segment& planned, float distance, const PlanContext& context) {
    gpu::MotionRecord segment = planned.motion;  // still being planned: sealed here to be evaluated
    sealSegment(segment, context.library, context.model);
    const glm::vec2 origin(segment.origin.x, segment.origin.z);
    auto reached = [&](float elapsed) {
        const MotionState s = evaluateMotion(segment, elapsed, context.library, context.model);
        return glm::distance(groundOf(s), origin) >= distance;
    };
    float low = 0.0f, high = 1.0f;
    while (!reached(high)) {
        low = high;
        high *= 2.0f;
        if (high > 600.0f) return high;  // a gait too slow to get there: try again later
    }
    // To a tenth of a millisecond (0.15 mm at a run's speed, far below a frame): every evaluation inside
    // the segment's curved part is a whole quadrature, and planning a large crowd is mostly these.
    constexpr float kPrecisionSeconds = 1e-4f;
    for (int i = 0; i < 24 && high - low > kPrecisionSeconds; ++i) {
        const float middle = 0.5f * (low + high);
        (reached(middle) ? high : low) = middle;
    }
    return high;
}

}  // namespace crowd
