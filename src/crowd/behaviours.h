#pragma once
// Behaviours: what characters do next, planned one motion segment at a time (crowd/motion.h) when the
// previous segment's plan runs out. Every choice comes from a hash of (seed, character, plan count),
// never from the frame or the thread, so the same seed gives the same crowd at the same time on any
// machine and at any frame rate.
//   in place: the paper's crowd; each character loops its clip where it stands, forever.
//   march:    a formation in step: stand, march out, turn about, march back, turn about, halt, repeat.
//   mill:     each character stands a while, picks a target near home, sets off walking or running,
//             speeds up or slows down on the way, and stops there; every change is a crossfade.
#include <cstdint>
#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "anim/clip_library.h"
#include "crowd/gaits.h"
#include "gpu_types.h"

namespace crowd {

enum class Behaviour { InPlace, March, Mill };
const char* behaviourName(Behaviour behaviour);
// "in-place", "march", "mill"; false for anything else.
bool parseBehaviour(const std::string& name, Behaviour& behaviour);

struct BehaviourSettings {
    Behaviour kind = Behaviour::InPlace;
    std::uint32_t seed = 1;
    float millRadius = 8.0f;    // metres from home within which milling characters pick targets
    float marchLength = 24.0f;  // metres a formation marches before it turns about
};

// A character's planner state between segments.
struct Agent {
    enum class Stage : std::uint8_t { Forever, Stand, Cruise, MarchOut, TurnAbout, MarchBack, TurnHome, Halt, Play };
    static constexpr float kNever = std::numeric_limits<float>::infinity();
    Behaviour kind = Behaviour::InPlace;
    Stage stage = Stage::Forever;
    bool commanded = false;  // following a program's command (Crowd::moveTo / play) instead of a behaviour
    float due = kNever;      // when the next segment must be planned
    std::uint32_t plans = 0; // segments planned so far: salts this character's random choices
    glm::vec2 home{0.0f};    // where a milling character started
    glm::vec2 target{0.0f};  // where it is going
    std::int32_t gait = Gaits::kNone;  // the clip it travels with
    float rate = 1.0f;       // playback rate of its gait (variety)
    float fade = 0.3f;       // crossfade of a commanded clip (Stage::Play)
};

struct PlanContext {
    const anim::ClipLibrary& library;
    std::uint32_t model;
    const Gaits& gaits;
    const BehaviourSettings& settings;
    std::uint32_t character;
};

// Starts a character's behaviour at time 0 from its first segment (the in-place loop its layout gave
// it): returns the segment to follow and sets the agent's stage and due time.
gpu::MotionRecord startBehaviour(Agent& agent, const gpu::MotionRecord& first, const PlanContext& context);

// The segment that follows `current` from agent.due on; advances the agent's stage and due time.
gpu::MotionRecord planNext(Agent& agent, const gpu::MotionRecord& current, const PlanContext& context);

// A segment that crossfades from wherever `current` is at `start` to `clip` (played `rate` times its
// natural speed) over `fade` seconds, travelling by root motion, heading unchanged.
gpu::MotionRecord transition(const gpu::MotionRecord& current, float start, std::uint32_t clip, float rate, float fade,
                             const PlanContext& context);
// Makes `segment` turn from its start heading to `heading` (the shorter way) at `turnRate` rad/s.
void turnTowards(gpu::MotionRecord& segment, float heading, float turnRate);
// The heading that carries a character of the segment's to-clip towards `target` from `from`.
float headingTowards(const glm::vec2& from, const glm::vec2& target, std::uint32_t clip, const PlanContext& context);
// Seconds into `segment` when the character is `distance` metres from the segment's origin (bisection
// on the closed form; the straight-line distance, so meant for paths that barely curve).
float timeToCover(const gpu::MotionRecord& segment, float distance, const PlanContext& context);

}  // namespace crowd
