#pragma once
// When a milling character's episodes start, and the closed-form state each starts from (crowd/mill.h
// plans the trip in between). Episode 0 starts at 0 s from the layout: home, facing and at the phase
// it was laid out with. Episode k > 0 starts at (k + offset) x Rhythm::millEpisode seconds, the offset
// drawn per character so the crowd never stops in step; episode 0's wait is longer by offset episodes,
// so the crowd sets off over its first episode rather than all at once (a crowd setting off within
// the same few seconds planned three times its steady share a frame, a stall at its start),
// standing at target k, facing the way from target k - 1, at a phase drawn for the episode. Targets
// alternate between near home (even k) and a ring out to millRadius (odd k), so that every trip is at
// least kShortestTrip long and at most the near radius plus the ring's: the longest fits an episode.
#include <cstdint>

#include <glm/glm.hpp>

#include "crowd/behaviours.h"

namespace crowd {

inline constexpr float kShortestTrip = 2.0f;      // metres
inline constexpr float kWait = 1.0f;              // a character sets off within 1 s of its episode's start

// Choices made at an episode's boundary are salted with kBoundary in place of a plan count, apart from
// the choices made within the episode.
inline constexpr std::uint32_t kBoundary = 0xFFFFFFFFu;

double millEpisodeStart(std::uint32_t episode, const PlanContext& context);
// The episode under way at `time`.
std::uint32_t millEpisodeAt(double time, const PlanContext& context);
// Where episode k starts standing, facing where, at which phase of the standing clip.
glm::vec2 millTarget(const Agent& agent, std::uint32_t episode, const PlanContext& context);
float millHeading(const Agent& agent, std::uint32_t episode, const PlanContext& context);
float millPhase(const Agent& agent, std::uint32_t episode, const PlanContext& context);
// How long the standing before setting off lasts in episode k (in episode 0: its offset's share of an
// episode more).
float millWait(std::uint32_t episode, const PlanContext& context);

// Seconds an episode lasts for this model: the wait, the longest trip at the slowest walk (with headroom
// for its turns), the stop and a rest of at least a cycle of the standing clip.
double millEpisodeLength(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                         const BehaviourSettings& settings);

}  // namespace crowd
