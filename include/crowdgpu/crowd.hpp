// crowdgpu: the crowd, Vulkan-free (link crowdgpu::core).
//
// Every character has its model, clip, phase, speed, scale and tint, and moves by a plan: looping in
// place (the paper's crowd), marching in formation or milling about, or by the host's commands.
// Motion is closed form: any character's state at any time costs a few operations, on the CPU here
// or on the GPU in the renderer. advanceTo(time) is the one call that changes plans; a renderer reads
// the crowd when it records a frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "crowdgpu/model.hpp"

namespace crowdgpu {

namespace detail { struct CrowdData; }

// What a character is when it enters the crowd: it plays `clip` in place until its behaviour or a
// command moves it.
// Character::props for a character that does not choose its props.
inline constexpr std::uint32_t kModelProps = 0xFFFFFFFFu;

struct Character {
    std::uint32_t model = 0;     // index into the crowd's models
    std::uint32_t clip = 0;      // index into its model's clips
    float phase = 0.0f;          // seconds added to the crowd's clock for this character
    float speed = 1.0f;          // playback rate
    float position[3] = {0.0f, 0.0f, 0.0f};  // metres; y up, characters stand on y = 0
    float heading = 0.0f;        // radians about +y; 0 faces +z
    float scale = 1.0f;
    float tint[3] = {1.0f, 1.0f, 1.0f};  // linear colour multiplier
    // Bit k: it carries its model's prop k (Model::propName); kModelProps: chosen by each prop's share
    // and the crowd's seed (Crowd::character reports the choice). Bits past the model's props are ignored.
    std::uint32_t props = kModelProps;
};

// The most models one crowd mixes (the renderer's per-model tables are this long).
inline constexpr std::uint32_t kMaxCrowdModels = 16;

// Scene times every call takes (advanceTo, stateAt, jointWorld, events, moveTo, play, a frame's time):
// finite and within +-kLargestTime seconds (317 years: a run started at 1e9 s, the latest start the
// programs take and the library is tested at, as exact as at 0 s, goes on for centuries). Any other
// value, and any non-finite position, speed, scale, phase, heading, tint, rate or fade, is refused with
// Error(InvalidArgument) naming it (docs/embedding.md, "Argument ranges").
inline constexpr double kLargestTime = 1e10;
// The longest window (to - from, seconds) events() answers: a frame's is a few milliseconds.
inline constexpr double kLargestEventWindow = 3600.0;

enum class Behaviour { InPlace, March, Mill };
// "in-place", "march", "mill": for reports and menus.
const char* behaviourName(Behaviour behaviour);

// A square grid centred on the origin, with seeded jitter of position, heading, phase, speed and tint.
struct GridLayout {
    std::uint32_t count = 1024;
    std::uint32_t seed = 1;
    std::vector<float> weights;  // per model: its share of the crowd (empty: equal)
    std::vector<std::int32_t> clips;  // per model: the clip to play (-1 or missing: "walk", else the first)
    bool randomClips = false;    // every character picks a random clip of its model
    bool formation = false;      // an exact grid in step (marching)
    float depthRatio = 1.0f;     // rows over columns: 1 a square, 4 a column 4x as deep (z) as wide (> 0)
    float scaleVariation = 0.0f; // each character's scale varies by up to this fraction either way
    float tintVariation = 0.0f;  // and each tint channel by up to this one
    std::vector<float> scales;   // per model: a scale for all its characters (empty or missing: 1)
    bool props = true;           // characters carry their models' props by share and seed; false: none
};

// Where a character is and what it plays at a time.
struct CharacterState {
    float position[3];
    float heading;
    std::uint32_t clipFrom, clipTo;  // crossfading from one to the other (equal when not)
    float weight;                    // of clipTo
    float phase;                     // normalized, in cycles
};

// An animation event a character fired (Crowd::events): event `event` of its model's clip `clip`
// (Model::eventName, eventTime) at scene time `time`.
struct Event {
    std::uint32_t character;
    std::uint32_t clip;
    std::uint32_t event;
    double time;
};

class Crowd {
public:
    // Throws Error(InvalidArgument) naming the character whose model or clip does not exist.
    Crowd(std::vector<Model> models, std::vector<Character> characters, Behaviour behaviour = Behaviour::InPlace,
          std::uint32_t seed = 1);
    static Crowd grid(std::vector<Model> models, const GridLayout& layout, Behaviour behaviour = Behaviour::InPlace);
    ~Crowd();
    Crowd(Crowd&&) noexcept;
    Crowd& operator=(Crowd&&) noexcept;

    std::uint32_t size() const;
    const std::vector<Model>& models() const;
    // Adds a character under the crowd's behaviour; returns its index. A renderer sizes its buffers
    // when it is made: spawn before making one.
    std::uint32_t spawn(const Character& character);
    // From time `at` (or once its crossfade ends) walk to (x, z) with clip `gait` (-1: the model's walk)
    // at `rate` times its speed, and stop there.
    void moveTo(std::uint32_t character, float x, float z, double at, std::int32_t gait = -1, float rate = 1.0f);
    // From time `at` crossfade over `fade` seconds to `clip` at `rate` and keep playing it.
    void play(std::uint32_t character, std::int32_t clip, double at, float fade = 0.3f, float rate = 1.0f);
    // Plans every character up to `time` seconds: the host calls it once per frame, before recording.
    // Cost: the characters whose plan ran out (none for an in-place crowd; about 4,000 a 60 Hz frame of
    // a milling 1,000,000, 3 ms on 16 cores). A time far ahead costs no more than one just past every
    // plan: each character starts the episode holding it from a closed-form state (a milling 1,000,000
    // jumping to 30 s or to 1e6 s: about 4 s on 2 cores, once). Times are doubles: a crowd is as exact
    // at 1e9 s as at 0 s.
    void advanceTo(double time);
    CharacterState stateAt(std::uint32_t character, double time) const;
    // The character as it entered the crowd (its home position, model, scale, ...).
    Character character(std::uint32_t character) const;
    // Every character's skinning matrices at `time` (after advanceTo), on the CPU: 12 floats per joint
    // (the three rows of a 3x4 matrix), characters in order, each its model's jointCount() joints;
    // `rows` is resized to 12 x paletteJoints(). On every core (`allCores`) or the calling thread
    // only. About 50 ns per joint per core. The renderer's GPU path does the same on the GPU.
    void computePalettes(double time, std::vector<float>& rows, bool allCores = true) const;
    std::uint64_t paletteJoints() const;

    // Joint `joint` (Model::findJoint) of `character` in world space at `time` seconds, on the CPU,
    // for game logic (aim, hit tests, a camera that follows a hand). Writes 12 floats to `out`: the
    // three rows of the 3x4 matrix [R*s | t], row-major as computePalettes' rows but without the
    // inverse bind (a palette row is this times the joint's inverse bind matrix). Its last column
    // is the joint's position; the rest its rotation times the character's scale.
    // Exact with what the renderer draws: the same motion, sampling, blending and hierarchy as the
    // CPU palettes (which the GPU path matches). Times: after advanceTo(t), any time from the start
    // of the segment before each character's current one (one replan back; further back for one that
    // replanned more than once since the advanceTo before, so every frame's window is known) on; a
    // later time than t follows the current plan (which a later advanceTo may replace). Throws Error(InvalidArgument)
    // for a character or joint that does not exist, or a time before what the crowd still knows.
    // Cost: one character's whole skeleton (about 50 ns a joint), allocation-free once warm. Not to
    // be called while another thread advances the crowd or computes palettes.
    void jointWorld(std::uint32_t character, std::uint32_t joint, double time, float out[12]) const;

    // The animation events (Model::eventCount) that `count` characters fire at times t with
    // from < t <= to, on the CPU: `out` is cleared and filled, by character in the order given, each
    // character's in time order. An event fires each time the character's phase passes its point in
    // the clip's cycle; its time is solved from the closed-form motion (rate changes, crossfades and
    // replans included), so a window gives the same events in one call as split over frames. In a
    // crossfade two events of the same name and joint, one in each clip (a walk's and a run's
    // footstep of one foot), fire once, where the phase meets their points blended by the weight,
    // reported as the event of the clip that weighs more then; any other event fires from its clip
    // while that clip weighs more (the clip faded to from half way on). The window obeys jointWorld's times: ask for each frame's (previous time, time] after
    // advanceTo(time); a window reaching back before a character's previous segment throws
    // Error(InvalidArgument), as do a character that does not exist and a window longer than
    // kLargestEventWindow. Cost: about 100 ns a
    // character for a frame's window (docs/events.md), calling thread only; safe to call from
    // several threads at once (it changes nothing).
    void events(const std::uint32_t* characters, std::size_t count, double from, double to,
                std::vector<Event>& out) const;
    // The same window with a limit: returns how many events fire and lists them in `out` only when
    // they are at most `capacity` (else `out` is left empty), so the memory a call takes is bounded
    // by the caller. Capacity 0: the count alone, with no storage at all.
    std::uint64_t events(const std::uint32_t* characters, std::size_t count, double from, double to,
                         std::vector<Event>& out, std::size_t capacity) const;

    // The ground the crowd stands on: centre (x, y, z) and radius in metres; its tallest model's height.
    void bounds(float center[3], float& radius, float& tallest) const;

    // The library's side (opaque to hosts).
    explicit Crowd(std::unique_ptr<detail::CrowdData> data);
    detail::CrowdData& data() { return *data_; }
    const detail::CrowdData& data() const { return *data_; }

private:
    std::unique_ptr<detail::CrowdData> data_;
};

// Host bytes a crowd of `characters` of these models takes (its state, plans and the renderer's
// per-character records; with `cpuPalettes`, the CPU animation's matrices too). Errs high: compare
// it with the memory available before building a very large crowd.
std::uint64_t hostBytesNeeded(const std::vector<Model>& models, std::uint64_t characters, bool cpuPalettes);

// The CPU threads the library's parallel work shares (Crowd::advanceTo's planning, computePalettes on
// every core, the renderer's CPU animation), counting the calling thread: 1 keeps it all on the caller's
// thread, 0 (the default) takes one per core. A host with its own job system can leave it cores. The
// results do not depend on it. Call it before any crowd work or while no thread uses a crowd: the
// workers are made again. Throws Error (InvalidArgument) above 1024.
void setWorkerThreads(unsigned threads);
// The threads that work is shared by now, the calling thread's included.
unsigned workerThreads();

}  // namespace crowdgpu
