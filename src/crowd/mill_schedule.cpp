#include "crowd/mill_schedule.h"

#include <algorithm>
#include <cmath>

#include "crowd/plan_steps.h"
#include "crowd/standing.h"

namespace crowd {
namespace {

constexpr float kShortestRest = 1.5f;
// Headroom over a straight walk to the target at the slowest rate: the turns' arcs and re-aims.
constexpr float kTripHeadroom = 1.15f;
enum Salt : std::uint32_t { kOffset = 100, kTargetAngle, kTargetRadius, kPhase, kWaitSalt };

float nearRadius(const BehaviourSettings& settings) { return settings.millRadius / 3.0f; }
float ringInner(const BehaviourSettings& settings) { return nearRadius(settings) + kShortestTrip; }
float ringOuter(const BehaviourSettings& settings) { return std::max(settings.millRadius, ringInner(settings)); }

double offsetOf(const PlanContext& context) { return unit(context, 0, kBoundary, kOffset); }

}  // namespace

double millEpisodeStart(std::uint32_t episode, const PlanContext& context) {
    if (episode == 0) return 0.0;
    return (static_cast<double>(episode) + offsetOf(context)) * context.rhythm.millEpisode;
}

std::uint32_t millEpisodeAt(double time, const PlanContext& context) {
    const double guess = std::floor(time / context.rhythm.millEpisode - offsetOf(context));
    // Clamped (a NaN guess to 0) before it becomes an index, and the walk below stops at the last one.
    constexpr std::uint32_t kLast = 4000000000u;
    auto episode = static_cast<std::uint32_t>(guess > 0.0 ? std::min(guess, static_cast<double>(kLast)) : 0.0);
    // The division may round across a boundary: settle on the episode whose start is at or before `time`.
    while (episode > 0 && millEpisodeStart(episode, context) > time) --episode;
    while (episode < kLast && millEpisodeStart(episode + 1, context) <= time) ++episode;
    return episode;
}

glm::vec2 millTarget(const Agent& agent, std::uint32_t episode, const PlanContext& context) {
    const glm::vec2 home(agent.home.x, agent.home.z);
    if (episode == 0) return home;
    const float angle = 2.0f * kPi * unit(context, episode, kBoundary, kTargetAngle);
    const float u = unit(context, episode, kBoundary, kTargetRadius);
    const BehaviourSettings& s = context.settings;
    const float inner = episode % 2 == 0 ? 0.0f : ringInner(s);
    const float outer = episode % 2 == 0 ? nearRadius(s) : ringOuter(s);
    const float radius = std::sqrt(inner * inner + u * (outer * outer - inner * inner));  // uniform over the area
    return home + radius * glm::vec2(std::cos(angle), std::sin(angle));
}

float millHeading(const Agent& agent, std::uint32_t episode, const PlanContext& context) {
    if (episode == 0) return agent.homeHeading;
    return headingAlong(millTarget(agent, episode, context) - millTarget(agent, episode - 1, context));
}

float millPhase(const Agent& agent, std::uint32_t episode, const PlanContext& context) {
    return episode == 0 ? agent.homePhase : unit(context, episode, kBoundary, kPhase);
}

float millWait(std::uint32_t episode, const PlanContext& context) {
    // Episode 0 lasts from 0 s to episode 1's start, (1 + offset) episodes: standing the offset's share
    // first leaves its trip an ordinary episode's time.
    const double first = episode == 0 ? offsetOf(context) * context.rhythm.millEpisode : 0.0;
    return static_cast<float>(first + kWait * unit(context, episode, kBoundary, kWaitSalt));
}

double millEpisodeLength(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                         const BehaviourSettings& settings) {
    const auto walk = static_cast<std::uint32_t>(gaits.walk);
    const float slowest = glm::length(library.stride(model, walk)) * cyclesPerSecond(library, model, walk, kSlowestGaitRate);
    const Rhythm unknown;
    const PlanContext context{library, model, gaits, settings, unknown, 0};
    const float turn = kPi / kTurnRate;
    const float longestTrip = nearRadius(settings) + ringOuter(settings);
    const float standCycle = holdsWalkStill(context) ? 0.0f : library.duration(model, standingClip(context));
    return kWait + std::max(kStartFade, turn) + kTripHeadroom * longestTrip / slowest +
           std::max(longestStop(context), turn) + std::max(kShortestRest, standCycle);
}

}  // namespace crowd
