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

// Who moves a character (docs/host-driven.md): the crowd's behaviour (and commands), or the host's
// samples of where it is, from the host's memory (Crowd::drive; a character of the behaviour becomes
// one at its first sample) or from a device buffer the host's own pass fills each frame
// (Renderer::recordCompute's DeviceSamples; declared when the character enters: the CPU never sees
// those samples, so a CPU query of such a character is refused).
enum class MotionSource { Behaviour, HostSamples, DeviceSamples };

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
    MotionSource motion = MotionSource::Behaviour;
};

// The most models one crowd mixes (the renderer's per-model tables are this long).
inline constexpr std::uint32_t kMaxCrowdModels = 16;

// A character of a crowd whose population changes: its slot (the index every per-character query
// takes) and the slot's generation (how many characters the slot has held). Once the character is
// removed the handle is stale, and every call that takes it refuses it, even after a new character
// took the slot. Generation 0 is never valid.
struct CharacterHandle {
    std::uint32_t slot = 0;
    std::uint32_t generation = 0;
};

// The most characters of each model a crowd holds at once, fixed when it is made: a slot each
// (characters enter and leave by Crowd::spawn and remove; a renderer sizes its buffers from the slots).
// perModel[m]: model m's; an entry left out, or below the model's initial characters, is that count, so
// a crowd made without capacity holds exactly its characters (a removal frees a slot for its model).
struct CrowdCapacity {
    std::vector<std::uint32_t> perModel;
    // Keys each slot keeps for a driven character (1 to 64): the samples around the time drawn, which
    // lags the newest by DrivenTiming::delay, so at least delay x the sample rate + 2 (kDrivenKeys, 8,
    // covers 50 Hz samples at a 0.1 s delay). 32 bytes a key a slot on the device (and on the host once
    // a character is driven from its memory). 0, the default: kDrivenKeys when any of the crowd's first
    // characters is driven, else none, so a crowd of behaviours pays nothing; a crowd that spawns or
    // drives characters later gives a count.
    std::uint32_t drivenKeys = 0;
};
inline constexpr std::uint32_t kDrivenKeys = 8;

// The ground as the host gives it (docs/host-driven.md, "Terrain"): heights on a regular grid over a
// rectangle of the ground, bilinear between samples, the edge's heights beyond it. Every character stands
// on it: its height is added to the character's own y, wherever the character is.
struct Heightfield {
    std::uint32_t columns = 0, rows = 0;  // samples along x and along z (2 to 2^25 in all)
    const float* heights = nullptr;       // metres, row-major: sample (column, row) at column + row x columns
    float origin[2] = {0.0f, 0.0f};       // world (x, z) of sample (0, 0)
    float size[2] = {0.0f, 0.0f};         // world width (x) and depth (z): the last sample at origin + size
};

// ---- Characters the host drives (docs/host-driven.md) ----
// A batch of samples from the host's memory, structure of arrays: sample i says that characters[i] was
// at (x[i], z[i]) (world metres on the ground; the terrain gives the height) at times[i] (scene
// seconds), facing headings[i] (radians about +y, 0 facing +z) when `headings` is given and the entry is
// a number (NaN, or no array: the body turns towards the motion).
struct SampleBatch {
    const CharacterHandle* characters = nullptr;
    const double* times = nullptr;
    const float* x = nullptr;
    const float* z = nullptr;
    const float* headings = nullptr;  // may be null
    std::size_t count = 0;
};
struct DriveResult {
    std::size_t applied = 0;  // samples that became keys
    std::size_t late = 0;     // samples no later than their character's newest: ignored (networks reorder)
};
// How a driven character is drawn from its samples: at the frame's time less `delay` (seconds), between
// the two samples around it, as a network game's interpolation buffer does (cover the samples' interval
// and their jitter); past its newest sample it goes on at its last velocity for at most `extrapolate`
// seconds, then comes to rest.
struct DrivenTiming {
    double delay = 0.1;
    double extrapolate = 0.5;
};
// How a model's driven characters choose their gait by speed: standing below walkFrom (m/s), walking up
// to runFrom, running above (each gait stays hysteresis x its band's edge past it); a whole change of gait
// crossfades over `fade` seconds, both clips at the same phase; every clip plays at the rate that carries
// its stride (measured when the model loads) at the ground speed, so the feet do not slide. The body turns
// towards the motion at most turnRate rad/s, and not for motion slower than turnSpeed m/s. A model starts
// with walking from a tenth of its walk's own speed and running from half way between its walk's and its
// run's (Crowd::gaitSettings).
struct GaitSettings {
    float walkFrom = 0.0f;
    float runFrom = 0.0f;
    float hysteresis = 0.1f;
    float fade = 0.3f;
    float turnRate = 4.0f;
    float turnSpeed = 0.05f;
};

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
    MotionSource motion = MotionSource::Behaviour;  // who moves the grid's characters
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
    // The characters take slots 0 to n-1 in order; each model's spare slots (`capacity`) follow, free.
    // Throws Error(InvalidArgument) naming the character whose model or clip does not exist.
    Crowd(std::vector<Model> models, std::vector<Character> characters, Behaviour behaviour = Behaviour::InPlace,
          std::uint32_t seed = 1, const CrowdCapacity& capacity = {});
    static Crowd grid(std::vector<Model> models, const GridLayout& layout, Behaviour behaviour = Behaviour::InPlace,
                      const CrowdCapacity& capacity = {});
    ~Crowd();
    Crowd(Crowd&&) noexcept;
    Crowd& operator=(Crowd&&) noexcept;

    // The slots, living or free (0 .. size()-1): every per-character index below is a slot. A query of a
    // free slot is refused. For a crowd made without spare capacity and never changed, the characters.
    std::uint32_t size() const;
    // The living characters.
    std::uint32_t liveCount() const;
    const std::vector<Model>& models() const;

    // ---- The population (between frames, at any time) ----
    // Adds a character in a free slot of its model, under the crowd's behaviour: it plays its clip as
    // if it had been there since time 0 (its phase from Character::phase), and fires no event before
    // the time the crowd was last advanced to. Returns its handle. Throws Error(CapacityExceeded) when
    // every slot of its model is taken, Error(InvalidArgument) for a model or clip that does not exist;
    // nothing changes then. Costs a slot's planning (microseconds); the renderer uploads that slot alone.
    CharacterHandle spawn(const Character& character);
    // A batch, for many at once (a wave, a server's update): handles[i] names characters[i]. All or none:
    // every character is checked and each model's free slots counted first, so a batch that does not fit
    // changes nothing (CapacityExceeded names the model). The slots are planned on every core.
    void spawn(const Character* characters, std::size_t count, CharacterHandle* handles);
    // The character leaves: it is drawn no more from the next recordCompute, and its slot is free for the
    // next spawn of its model. Throws Error(InvalidArgument) for a stale handle.
    void remove(CharacterHandle character);
    // A batch: all or none (a stale handle, or one given twice, refuses it whole, naming the handle).
    void remove(const CharacterHandle* characters, std::size_t count);
    // Whether the handle names a living character.
    bool alive(CharacterHandle character) const;
    // The handle of slot `slot`'s living character. Throws Error(InvalidArgument) for a free slot.
    CharacterHandle handle(std::uint32_t slot) const;
    // From time `at` (or once its crossfade ends) walk to (x, z) with clip `gait` (-1: the model's walk)
    // at `rate` times its speed, and stop there.
    void moveTo(std::uint32_t character, float x, float z, double at, std::int32_t gait = -1, float rate = 1.0f);
    // From time `at` crossfade over `fade` seconds to `clip` at `rate` and keep playing it.
    void play(std::uint32_t character, std::int32_t clip, double at, float fade = 0.3f, float rate = 1.0f);
    // ---- Driven characters (docs/host-driven.md) ----
    // Each sample becomes its character's next key; the renderer uploads the new keys alone (48 bytes
    // each). The whole batch is refused (Error(InvalidArgument) naming the first bad sample and its
    // character), with nothing applied, for a stale handle, a character driven by a device buffer, a
    // non-finite time or position, an infinite heading, missing arrays, or a crowd whose capacity has no
    // driven keys. A sample no later than its character's newest is ignored and counted, not an error.
    // Several samples of one character in a batch apply in the batch's order. On every core for a large
    // batch: about 30 ns a sample.
    DriveResult drive(const SampleBatch& samples);
    void setDrivenTiming(const DrivenTiming& timing);  // Error(InvalidArgument) outside 0 to 3,600 s
    DrivenTiming drivenTiming() const;
    // Error(InvalidArgument) for a model that does not exist or settings out of their ranges (walkFrom >= 0,
    // runFrom above it, hysteresis in [0, 1), fade >= 0, turnRate > 0, turnSpeed >= 0). Keys made from
    // then on follow them.
    void setGaitSettings(std::uint32_t model, const GaitSettings& settings);
    GaitSettings gaitSettings(std::uint32_t model) const;

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
    // (the three rows of a 3x4 matrix), slots in order, each its model's jointCount() joints (a free
    // slot's zeros);
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

    // The ground every character stands on, copied (columns 0: flat again, y = 0). Error(InvalidArgument)
    // naming the problem for fewer than 2 x 2 samples, heights that are not finite, or an extent that is not
    // positive; nothing changes then. The renderer uploads it at its next frame (it must have room:
    // RendererSettings::terrainSamples). Characters, their joints, events and the drawn ground follow it.
    void setTerrain(const Heightfield& ground);
    // The ground's height at (x, z), as characters stand on it.
    float groundHeight(float x, float z) const;

    // The ground the crowd stands on: centre (x, y, z) and radius in metres; its tallest model's height.
    // Measured from the living characters (and the driven ones' samples) when the population changed
    // (every slot: a millisecond a million), unless the host set world bounds.
    void bounds(float center[3], float& radius, float& tallest) const;
    // The ground the crowd may cover, the host's (its world, its simulation's domain; lo below hi on each
    // axis): the renderer fits the shadow map to it, so shadows do not change as characters come and
    // go, and the bounds cost nothing to measure. Error(InvalidArgument) for non-finite values.
    void setWorldBounds(const float lo[3], const float hi[3]);

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
