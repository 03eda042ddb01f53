#pragma once
// Behaviours: what characters do next, planned one motion segment at a time (crowd/segment.h) when the
// previous segment's plan runs out. Every choice comes from a hash of (seed, character, episode, plan
// count), never from the frame or the thread, so the same seed gives the same crowd at the same time on
// any machine and at any frame rate.
//   in place: the paper's crowd; each character loops its clip where it stands, forever.
//   march:    a formation in step: stand, march out, turn about, march back, turn about, halt, repeat
//             (crowd/march.h).
//   mill:     each character stands a while, sets off walking or running to a target near home, speeds
//             up or slows down on the way, and stops there; every change is a crossfade (crowd/mill.h).
// Both living behaviours are episodes whose first state is closed form (where, facing where, at which
// phase, from when), so reaching any time costs one episode of planning, not every plan since 0 s.
// A program's commands (crowd/commands.h) take a character out of its behaviour for good.
#include <cstdint>
#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "anim/clip_library.h"
#include "crowd/gaits.h"
#include "crowd/rhythm.h"
#include "crowd/segment.h"

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
    enum class Stage : std::uint8_t {
        Forever, Stand, Cruise, Bend, Stop, Rest, MarchOut, TurnAbout, MarchBack, TurnHome, Halt, Play
    };
    static constexpr double kNever = std::numeric_limits<double>::infinity();
    Behaviour kind = Behaviour::InPlace;
    Stage stage = Stage::Forever;
    bool commanded = false;  // following a program's command (Crowd::moveTo / play) instead of a behaviour
    std::uint32_t episode = 0;  // the mill episode or march cycle under way
    std::uint32_t plans = 0;    // segments planned in it (or under commands): salts the random choices
    double due = kNever;        // when the next segment must be planned
    double episodeEnd = kNever; // when the next episode starts (from a closed-form state)
    glm::vec3 home{0.0f};       // where the character started
    float homeHeading = 0.0f;   // and facing where
    float homePhase = 0.0f;     // at which phase of its first clip
    glm::vec2 target{0.0f};     // where it is going
    std::int32_t gait = Gaits::kNone;  // the clip it travels with
    float rate = 1.0f;          // playback rate of its gait (variety)
    float fade = 0.3f;          // crossfade of a commanded clip (Stage::Play)
    double stopCycles = 0.0;      // the whole cycles its planned stop lands on (crowd/standing.h)
    float bendTurn = 0.0f;        // the second leg of a bent arrival (crowd/arrival.h): its turn
    double bendLength = 0.0;      // and seconds
};

struct PlanContext {
    const anim::ClipLibrary& library;
    std::uint32_t model;
    const Gaits& gaits;
    const BehaviourSettings& settings;
    const Rhythm& rhythm;
    std::uint32_t character;
};

// Starts a character's behaviour at time 0 from its first segment (the in-place loop its layout gave
// it): returns the segment to follow and sets the agent's stage and due time.
Segment startBehaviour(Agent& agent, const Segment& first, const PlanContext& context);

// The segment that follows `current` from agent.due on; advances the agent's stage and due time.
Segment planNext(Agent& agent, const Segment& current, const PlanContext& context);

// When `time` lies past the episode under way (and no command is being followed), moves the agent
// straight to the episode holding `time`, whose first state is closed form, and returns its first
// segment in `segment`: what planNext would have reached by planning every segment in between.
bool skipTo(Agent& agent, double time, const PlanContext& context, Segment& segment);

}  // namespace crowd
