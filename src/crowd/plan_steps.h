#pragma once
// The steps behaviours and commands plan with: a crossfade into a clip, a turn, the heading towards a
// place, the time to cover a distance, and the seeded choices.
#include <cstdint>
#include <numbers>

#include <glm/glm.hpp>

#include "crowd/behaviours.h"

namespace crowd {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kTurnRate = 2.5f;  // rad/s: a brisk but natural turn towards a target
inline constexpr float kStartFade = 0.4f, kGaitFade = 0.5f, kStopFade = 0.5f;
// Behaviours play a gait at 0.85 to 1.15 times its natural rate (variety).
inline constexpr float kSlowestGaitRate = 0.85f, kGaitRateRange = 0.3f;

// A uniform number in [0, 1) from (seed, character, episode, plan, salt): the same on every machine.
float unit(const PlanContext& context, std::uint32_t episode, std::uint32_t plan, std::uint32_t salt);
// The agent's next choice: salted by the segments it has planned in its episode.
float unit(const Agent& agent, const PlanContext& context, std::uint32_t salt);

float wrapAngle(float angle);
glm::vec2 groundOf(const MotionState& state);
// The heading that faces along `way` (heading 0 faces +z).
float headingAlong(glm::vec2 way);

// A segment that crossfades from wherever `current` is at `start` to `clip` (played `rate` times its
// natural speed) over `fade` seconds, travelling by root motion, heading unchanged. A change of rate
// alone (the same clip) ramps the rate over the fade; no change takes no fade.
Segment transition(const Segment& current, double start, std::uint32_t clip, float rate, float fade,
                   const PlanContext& context);
// Makes `segment` turn from its start heading to `heading` (the shorter way) at `turnRate` rad/s.
void turnTowards(gpu::MotionRecord& segment, float heading, float turnRate);
// Makes `segment` turn by `angle` radians (either way, any amount) at `turnRate` rad/s.
void turnBy(gpu::MotionRecord& segment, float angle, float turnRate);
// The heading that carries a character of the segment's to-clip towards `target` from `from`.
float headingTowards(const glm::vec2& from, const glm::vec2& target, std::uint32_t clip, const PlanContext& context);
// Seconds into `segment` when the character is `distance` metres from the segment's origin (bisection
// on the closed form; the straight-line distance, so meant for paths that barely curve).
float timeToCover(const Segment& segment, float distance, const PlanContext& context);

}  // namespace crowd
