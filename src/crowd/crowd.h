#pragma once
// The crowd: every character's model, variety and motion, the API a program drives it with, and the
// CPU path that turns it into bone matrices each frame. A crowd may mix models (soldiers beside horses
// beside glTF characters); a character names its model by index into the crowd's model list.
//
// Motion is a closed-form segment per character (crowd/motion.h). Behaviours (crowd/behaviours.h) or
// commands plan a new segment when the last one's plan runs out; advanceTo(time) does that planning,
// and only the characters it replans change for the GPU. Scene time is a double; the GPU gets each
// segment relative to the crowd's epoch (crowd/epoch.h), and the CPU reference evaluates the same
// records with the same float arithmetic.
#include <cstdint>
#include <deque>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "anim/affine.h"
#include "anim/clip_library.h"
#include "crowd/behaviours.h"
#include "crowd/change_log.h"
#include "crowd/driven.h"
#include "crowd/events.h"
#include "crowd/gaits.h"
#include "crowd/motion.h"
#include "crowd/population.h"
#include "crowd/rhythm.h"
#include "crowd/terrain.h"
#include "crowd/segment.h"
#include "crowd/wake_calendar.h"
#include "crowd/worker_pool.h"
#include "gpu_types.h"
#include "model/skinned_model.h"

namespace crowd {

// Character::props when the character does not choose: its model's props by their shares.
inline constexpr std::uint32_t kModelProps = 0xFFFFFFFFu;

// What a character is when it enters the crowd: it plays `clip` in place from time 0 (the paper's
// crowd) until its behaviour or a command moves it.
struct Character {
    std::uint32_t clip = 0;
    float timeOffset = 0.0f;  // seconds added to the global time (the character's phase)
    float speed = 1.0f;       // playback rate
    glm::vec3 position{0.0f};
    float heading = 0.0f;     // radians about +y; 0 faces +z
    std::uint32_t model = 0;  // index into the crowd's models
    float scale = 1.0f;       // uniform scale of the model
    glm::vec3 tint{1.0f};     // colour multiplier, so a crowd of one model does not look cloned
    // Bit k: it carries its model's prop k (model/attach_prop.h); kModelProps: the crowd draws them by
    // each prop's share (model::defaultPropsCarried), so a grid gets its variety without choosing.
    std::uint32_t props = kModelProps;
    // Who moves it: the crowd's behaviour, or the host's samples (crowd/driven.h): from its memory
    // (Crowd::drive; a character of the behaviour becomes one at its first sample), or from a device
    // buffer the renderer reads (declared here: the CPU never sees those samples).
    Driven driven = Driven::No;
};

struct LayoutOptions {
    std::uint32_t count = 1;
    std::uint32_t seed = 1;
    // Per model: the clip its characters play; -1 (or a missing entry): the model's default clip.
    std::vector<int> clips;
    // Every character picks a random clip of its model (overrides `clips`).
    bool randomClips = false;
    // Per model: its share of the crowd (relative weights); empty: equal shares.
    std::vector<float> weights;
    // Per model: uniform scale of its characters; empty: 1.
    std::vector<float> scales;
    // A formation: exact grid, every character facing +z at phase 0 and speed 1 (marching in step).
    bool formation = false;
    // Rows over columns of the grid: 1 a square; 4 a column four times as deep (along z, the way a
    // formation marches) as it is wide. Must be positive.
    float depthRatio = 1.0f;
    // Each character's scale varies by up to this fraction either way, and each colour channel of its
    // tint by up to this one (seeded), so no two match.
    float scaleVariation = 0.0f;
    float tintVariation = 0.0f;
    // Characters carry their models' props by each prop's share and the seed; false: none carries any.
    bool props = true;
};

// Characters on a square grid centred on the origin, facing +z, with seeded jitter of position,
// heading, phase and speed so no two move in lockstep, a seeded brightness tint, and models drawn
// by weight. The grid's spacing fits the widest model, so neighbours never intersect.
std::vector<Character> gridLayout(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options);

// The clip a crowd plays when none is named: "walk" if present, else the first.
std::uint32_t defaultClip(const model::SkinnedModel& model);

// The brightness variation of character `index` of a grid (0.82 to 1.18, a hash of the index).
float brightnessVariation(std::uint32_t index);

// World transform of a character: its scale, then its heading, then its position.
glm::mat4 characterTransform(const Character& character);

// How many characters of each model the crowd holds at most at once: a slot each, fixed when the crowd is
// made (crowd/population.h). An entry left out, or below the model's initial characters, is that count:
// a crowd made without one holds exactly its characters (removing one frees a slot for another of its model).
struct Capacity {
    std::vector<std::uint32_t> perModel;
    // Keys each slot keeps for a driven character (crowd/driven.h): the samples around the time drawn,
    // which lags the newest by the delay. At most 64. 0: kDefaultDrivenKeys when any first character is
    // driven, else none (no character drivable, the memory saved).
    std::uint32_t drivenKeys = 0;
};
inline constexpr std::uint32_t kMostDrivenKeys = 64;
inline constexpr std::uint32_t kDefaultDrivenKeys = 8;

// A batch of the host's samples (Crowd::drive), structure of arrays in the host's memory: sample i is
// characters[i]'s at times[i] (scene seconds) at (x[i], z[i]) (world metres), facing headings[i]
// (radians about +y) when `headings` is given and the entry is a number (NaN: towards the motion).
struct SampleBatch {
    std::span<const Handle> characters;
    std::span<const double> times;
    std::span<const float> x, z;
    std::span<const float> headings;  // empty, or one per sample
};
struct DriveResult {
    std::size_t applied = 0;  // samples that became keys
    std::size_t late = 0;     // samples no later than their character's newest key: ignored
};

// What a slot's character looks like on the GPU (CharacterRecord's tint and pose.z): its tint, its scale
// (0 for a free slot: culling skips it) and the props it carries.
struct Identity {
    glm::vec4 tintScale{1.0f};
    std::uint32_t props = 0;
    std::uint32_t generation = 0;  // the slot's (crowd/population.h): which character holds it
};

class Crowd {
public:
    // The models must outlive the crowd. Throws gpu::Error when a character names a model or clip
    // that does not exist, when there are more than MAX_MODELS models, or when the slots would pass
    // 2^32. The characters take slots 0 to n-1 in order; each model's spare slots (capacity) follow.
    Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters,
          const BehaviourSettings& behaviour = {}, const Capacity& capacity = {});
    // A crowd of one model.
    Crowd(const model::SkinnedModel& model, std::vector<Character> characters, const BehaviourSettings& behaviour = {});

    // Slots, living or free: every per-character array (here and on the GPU) has this many entries.
    std::uint32_t size() const { return static_cast<std::uint32_t>(characters_.size()); }
    // Each slot's character, or for a free slot what it last held (its model is the slot's).
    const std::vector<Character>& characters() const { return characters_; }
    const Population& population() const { return population_; }
    bool alive(std::uint32_t slot) const { return population_.alive(slot); }
    // A number that differs between any two crowds made in this process (moves keep it): a renderer
    // that is handed another crowd uploads it whole.
    std::uint64_t id() const { return id_; }
    // The slots' models as one number: two crowds whose slots hold the same models of the same
    // addresses match (what a renderer laid out for one fits the other).
    std::uint64_t layoutKey() const { return layoutKey_; }
    Identity identity(std::uint32_t slot) const;
    const std::vector<const model::SkinnedModel*>& models() const { return models_; }
    const model::SkinnedModel& model(std::uint32_t index) const { return *models_[index]; }
    const model::SkinnedModel& modelOf(std::uint32_t character) const { return *models_[characters_[character].model]; }
    // Every model's clips, flattened (the CPU jobs' input and what the GPU path uploads).
    const anim::ClipLibrary& library() const { return library_; }
    const Gaits& gaits(std::uint32_t model) const { return gaits_[model]; }
    const BehaviourSettings& behaviour() const { return behaviour_; }

    // ---- Driving the crowd ----
    // Adds a character playing its clip in place under the crowd's behaviour, in a free slot of its
    // model; returns its handle. Its motion is planned from time 0 as the initial characters' is, and
    // queries before the time the crowd was last advanced to see no events of it. Throws gpu::Error
    // (CapacityExceeded) when every slot of its model is taken, (InvalidArgument) for a model or clip
    // that does not exist; nothing changes then.
    Handle spawn(const Character& character);
    // A batch: every character checked and the capacity of each model counted before any slot is
    // taken (a batch that does not fit changes nothing); the slots' planning on every core. handles[i]
    // names characters[i].
    void spawn(const Character* characters, std::size_t count, Handle* handles);
    // The character leaves the crowd; its slot is free for the next of its model. Throws gpu::Error for a
    // stale handle.
    void remove(Handle handle);
    // A batch: every handle checked first (a stale one, or one given twice, refuses the batch whole).
    void remove(const Handle* handles, std::size_t count);
    // Throws gpu::Error (InvalidArgument) naming the character when `handle` is stale.
    void checkHandle(Handle handle) const;
    // From time `at` on (or once its current crossfade ends), walk to `target` (world x, z) with clip
    // `gait` (-1: the model's walk) at `rate` times its speed, turning on the way, and stop there.
    void moveTo(std::uint32_t character, glm::vec2 target, double at, std::int32_t gait = -1, float rate = 1.0f);
    // From time `at` on, crossfade over `fade` seconds to `clip` at `rate` and keep playing it; a clip
    // with root motion carries the character forward along its heading. Throws gpu::Error for a clip the
    // model lacks (a negative one too: what SkinnedModel::findClip returns for a missing name).
    void play(std::uint32_t character, std::int32_t clip, double at, float fade = 0.3f, float rate = 1.0f);
    // ---- Driven characters (crowd/driven.h) ----
    // Each sample becomes its character's next key (a character of the behaviour is driven by the
    // host's samples from its first one on). The whole batch is refused (gpu::Error naming the first bad
    // entry and its character), with nothing applied, for a stale handle, a character driven by a device
    // buffer, a non-finite time or position, an infinite heading, arrays of different lengths, or a crowd
    // made without driven keys; a sample no later than its character's newest key is ignored and counted
    // (networks reorder). Several samples of one character in a batch apply in the batch's order. On every
    // core for a large batch; about 30 ns a sample.
    DriveResult drive(const SampleBatch& batch);
    // The delay and extrapolation of every driven character; changes apply to every character at once.
    void setDrivenTiming(const DrivenTiming& timing);
    const DrivenTiming& drivenTiming() const { return timing_; }
    // A model's gait bands (for keys made from now on).
    void setGaitBands(std::uint32_t model, const GaitBands& bands);
    const GaitBands& gaitBands(std::uint32_t model) const { return bands_[model]; }
    // Each model's gaits as the GPU reads them.
    const std::vector<gpu::DrivenModel>& drivenModels() const { return drivenModels_; }
    Driven drivenBy(std::uint32_t slot) const { return characters_[slot].driven; }
    std::uint32_t drivenKeysPerSlot() const { return drivenKeysPerSlot_; }
    // The keys of the characters driven from the host's memory (empty until the first sample).
    const DrivenKeys& drivenKeys() const { return keys_; }
    // The keys made after change generation `since` (crowd/change_log.h), as (slot, key index) pairs in
    // the order made; false when the log no longer reaches back (a reader then takes every slot's ring).
    template <class F>
    bool forEachKeySince(std::uint64_t since, F&& f) const {
        return forEachKeyListSince(since, [&](const KeyLogList& list) {
            for (const auto& [slot, index] : list)
                if (keyStillHeld(slot, index)) f(slot, index);
        });
    }
    // The same a list at a time (one per change generation, in order), for a reader that stages a list on
    // every core: an entry is a key when keyStillHeld says so (a late sample's entry holds kNoKeySlot).
    struct KeyLogEntry {
        std::uint32_t slot, index;
        // Left unset by a resize: drive() grows the log by a batch and fills it on every core, and
        // zeroing a million entries first would cost a serial pass over 8 MB.
        KeyLogEntry() noexcept {}  // NOLINT(modernize-use-equals-default): = default would zero them
        KeyLogEntry(std::uint32_t s, std::uint32_t i) noexcept : slot(s), index(i) {}
    };
    using KeyLogList = std::vector<KeyLogEntry>;
    static constexpr std::uint32_t kNoKeySlot = ~0u;
    template <class F>
    bool forEachKeyListSince(std::uint64_t since, F&& f) const {
        if (since == ChangeLog::kEverything || since < keyLogFirst_) return false;
        for (std::uint64_t g = since + 1; g <= changes_.openGeneration(); ++g) f(keyLogOf(g));
        return true;
    }
    bool keyStillHeld(std::uint32_t slot, std::uint32_t index) const {
        return slot != kNoKeySlot && index + keys_.perSlot() >= keys_.count(slot);  // still in its ring
    }
    std::size_t keysSince(std::uint64_t since) const;
    // The clock the keys are evaluated on for a frame at `time`: seconds since the epoch, less the delay.
    float drivenClock(double time) const;

    // Plans every character's segments up to `time`. A behaviour's character whose episode ended
    // goes straight to the episode holding `time` (its start is closed form), so a late time costs one
    // episode of planning, as an early one does. Going back in time starts every plan over from there
    // (commands given so far are forgotten).
    void advanceTo(double time);
    // The characters whose segment the last advanceTo changed (with those spawned since the one before),
    // and a counter of advanceTo calls.
    const std::vector<std::uint32_t>& lastChanged() const { return lastChanged_; }
    std::uint64_t generation() const { return generation_; }
    // The slots whose record or identity changed (replans, spawns, removals), for renderers: a
    // renderer seals the open generation when it takes the changes for a frame (crowd/change_log.h).
    // Sealing changes nothing a host sees: it is the log's bookkeeping.
    const ChangeLog& changes() const { return changes_; }
    std::uint64_t sealChanges() const;
    // Each character's current segment relative to epoch(): what the GPU's motion pass evaluates at
    // (float)(time - epoch()).
    const std::vector<gpu::MotionRecord>& segments() const { return segments_; }
    // The epoch of the time advanced to last (crowd/epoch.h).
    double epoch() const { return epoch_; }
    // Each character's current segment on the scene clock.
    const std::vector<Segment>& plans() const { return plans_; }
    // Segments planned since the crowd was made: what advancing it has cost.
    std::uint64_t plannedSegments() const { return planned_; }
    // Where character `index` is and what it plays at `time` (within its planned segment), evaluated
    // as the GPU does: its record at (float)(time - epoch()).
    MotionState stateAt(std::uint32_t index, double time) const;
    // The same at any time the crowd still knows exactly: the current segment (bit for bit what
    // stateAt gives, and what the GPU draws), or before its start the segment it replaced (evaluated
    // on today's epoch: equal to what was drawn then up to float rounding). Before the first plan's
    // start a character stands at that start, as drawn. Throws gpu::Error for a time before knownFrom().
    MotionState stateKnown(std::uint32_t index, double time) const;
    // The earliest time stateKnown answers for `index`: -infinity while its first plan holds, else the
    // start of the segment before its current one (one replan back; the earliest in earlier_ when it
    // replanned more than once in the last advanceTo), or the current one's start when
    // advanceTo skipped whole episodes to reach it.
    double knownFrom(std::uint32_t index) const { return knownFrom_[index]; }
    // When the character in slot `index` was spawned (-infinity for the crowd's first characters).
    double bornAt(std::uint32_t index) const { return bornAt_[index]; }
    // The segment `index` followed before its current one (valid when knownFrom() is finite and before
    // plans()[index].start).
    const Segment& previousPlan(std::uint32_t index) const { return previous_[index]; }

    // ---- The CPU animation path (the reference) ----
    // Writes the skinning matrices of every character at `time` (seconds): character c's joint j goes
    // to out[boneOffsets[c] + j]; with `records`, also each record's placement, clips and phase. Jobs
    // (sample, blend, hierarchy) per character, split over `pool`'s threads (default: every core).
    void animate(double time, std::span<gpu::BoneRows> out, std::span<const std::uint32_t> boneOffsets,
                 std::span<gpu::CharacterRecord> records = {}, WorkerPool* pool = nullptr) const;
    // The skinning matrices of one character (for tests and pose export).
    void animateCharacter(std::uint32_t index, double time, std::span<gpu::BoneRows> out) const;
    // A record's motion fields (placement, clips, phase) at `time`.
    void poseRecord(std::uint32_t index, double time, gpu::CharacterRecord& record) const;
    // Joint `joint` of character `index` in world space at `time` (stateKnown's times): the palette
    // job's world transform before the inverse bind, placement * root * local[root] * ... * local[joint].
    // Costs one character's sampling, blending and hierarchy (every joint: the hierarchy is one sweep).
    anim::Affine jointWorld(std::uint32_t index, std::uint32_t joint, double time) const;
    // The clip events (crowd/events.h) the given characters fire at times t with from < t <= to,
    // appended to `out`: by character in the order given, each in time order. The window must lie
    // within what the crowd knows (from >= knownFrom(c)); times after the last advanceTo follow the
    // current plans. Throws gpu::Error for a character that does not exist or a window it forgot.
    void events(std::span<const std::uint32_t> characters, double from, double to, EventSink& out) const;
    void events(std::span<const std::uint32_t> characters, double from, double to, std::vector<FiredEvent>& out) const {
        EventSink sink{&out};
        events(characters, from, to, sink);
    }

    // Centre and radius of the ground the living characters stand on (and may walk over), and the
    // tallest of them (a crowd with nobody: its first model's height). Measured again (over every slot)
    // only when the population changed since the last call, or the driven characters' samples reached
    // further; world bounds, when set, give the ground instead, at once.
    glm::vec3 center() const;
    float radius() const;
    float tallestHeight() const;
    // The ground every character stands on (crowd/terrain.h): its height is added to each character's y
    // wherever it is. Any time (a renderer uploads it at its next frame); the default is flat (y = 0).
    void setTerrain(const Terrain& terrain);
    const Terrain& terrain() const { return terrain_; }
    // Counts setTerrain calls: a renderer uploads the heights when it differs.
    std::uint64_t terrainVersion() const { return terrainVersion_; }

    // The ground the crowd may cover, from the host (its world, its simulation's domain): shadows are
    // fitted to it and it never moves as characters come and go. Empty (lo > hi): measured from the
    // characters.
    void setWorldBounds(const glm::vec3& lo, const glm::vec3& hi);

private:
    // What is wrong with `character` in this crowd ("names model 5 of 2": its model, clip, driving), or "".
    std::string characterProblem(const Character& character) const;
    // Plans slot `slot`'s character (characters_[slot], living) from time 0 afresh: planSlot touches the
    // slot's own state alone (spawns plan on every core), noteStarted the lists every slot shares.
    void startSlot(std::uint32_t slot);
    void planSlot(std::uint32_t slot);
    void noteStarted(std::uint32_t slot);
    // f(i) for i in [0, count), on every core for a large batch (each i touching its own slot alone).
    template <class F>
    void forEachOfBatch(std::size_t count, const F& f);
    // Plans character `character` up to `time`; returns the segments it planned.
    // Segments that left previous_ while the window since the last advance still needs them go to
    // `earlier`, in order.
    using EarlierSegments = std::vector<std::pair<std::uint32_t, Segment>>;
    std::uint32_t replan(std::uint32_t character, double time, EarlierSegments& earlier);
    // Adds an advance's earlier segments (a list per chunk of its due characters) to earlier_, and
    // moves each of those characters' knownFrom_ back to its first.
    void keepEarlier(std::vector<EarlierSegments>& chunks);
    // Calls f(segment, begin, end) for each segment `index` followed from knownFrom() on, in time
    // order: the earlier ones, the previous one, the current one (end: infinity).
    template <class F>
    void forEachKnownSegment(std::uint32_t index, F&& f) const;
    // When `character` next needs planning: its plan's end, or its episode's.
    double wakeOf(std::uint32_t character) const;
    // Restates the records of lastChanged_ relative to epoch_.
    void restateRecords();
    // `world` (one per joint, optional) receives the joints' world transforms.
    void animateState(std::uint32_t index, const MotionState& state, std::span<gpu::BoneRows> out,
                      std::span<anim::Affine> world = {}) const;
    static void writePose(const MotionState& state, gpu::CharacterRecord& record);
    // Throws gpu::Error for a slot out of range or free.
    void checkCharacter(std::uint32_t character) const;
    // stateAt before the terrain: what planning continues from (a segment's y is the character's own).
    MotionState flatStateAt(std::uint32_t index, double time) const;
    // The state raised onto the terrain.
    MotionState onGround(MotionState state) const;
    // Throws gpu::Error (Unsupported) for a character driven by a device buffer: the CPU does not know its motion.
    void checkKnowable(std::uint32_t character) const;
    // Makes a character of the behaviour driven by the host's samples: it holds where it is until its first key.
    void startDriving(std::uint32_t slot);
    // The state of a driven character (one with keys) at `time`.
    MotionState drivenState(std::uint32_t slot, double time) const;
    // Throws gpu::Error naming the first bad sample; returns whether any sample is for a character of
    // the behaviour (its first: it becomes driven).
    bool checkBatch(const SampleBatch& batch) const;
    void applySample(std::size_t i, const SampleBatch& batch, std::size_t& late);
    const KeyLogList& keyLogOf(std::uint64_t generation) const;
    void command(std::uint32_t character, double at);
    PlanContext planContext(std::uint32_t character) const;

    std::vector<const model::SkinnedModel*> models_;
    std::vector<Character> characters_;
    Population population_;
    mutable ChangeLog changes_;
    // Per slot: the time its character was spawned at (-infinity for the crowd's first characters):
    // events before it are not its.
    std::vector<double> bornAt_;
    std::uint64_t id_ = 0, layoutKey_ = 0;
    // Driven characters: the timing, each model's bands and GPU entry, the keys of host samples, and
    // per change generation the keys made in it (slot, index), the last ChangeLog::kKeptGenerations.
    Terrain terrain_;
    std::uint64_t terrainVersion_ = 0;
    DrivenTiming timing_;
    std::vector<GaitBands> bands_;
    std::vector<gpu::DrivenModel> drivenModels_;
    std::uint32_t drivenKeysPerSlot_ = 0;
    DrivenKeys keys_;
    // The bounds of center() and radius(): the host's world, or measured (with the population's version
    // they were measured at, and the reach of the driven samples so far).
    struct Bounds {
        glm::vec3 lo{1e30f}, hi{-1e30f};
        glm::vec3 center{0.0f};
        float farthest = 0.0f;  // from the centre
        float tallest = 0.0f;
    };
    Bounds world_;
    mutable Bounds measured_;
    mutable std::uint64_t measuredVersion_ = ~0ull;
    Bounds drivenReach_;  // the samples of host-driven characters
    std::uint64_t reachVersion_ = 0;  // counts drivenReach_'s growths
    const Bounds& bounds() const;
    mutable std::deque<KeyLogList> keyLog_;  // sealed, keyLogFirst_ + 1 on
    mutable KeyLogList keyLogOpen_;
    mutable std::uint64_t keyLogFirst_ = 0;
    std::vector<std::uint32_t> batchStamps_;  // per slot: the last batch that had a sample of it
    std::uint32_t batch_ = 0;
    anim::ClipLibrary library_;
    std::vector<Gaits> gaits_;
    std::vector<Rhythm> rhythms_;
    BehaviourSettings behaviour_;
    std::vector<Segment> plans_;
    // One replan back: the segment each character followed before plans_ (for queries of the recent
    // past: events in a frame's window, joints at a time just before a replan), and from when the crowd
    // knows each character's motion exactly (Crowd::knownFrom).
    std::vector<Segment> previous_;
    std::vector<double> knownFrom_;
    // Further back, for the few characters that replanned more than once in the last advanceTo (a
    // milling character entering an episode whose first segment lasts milliseconds): the segments
    // before previous_ that the window (advancedFrom_, plannedTo_] still needs: by character, each one's
    // in time order. Emptied by the next advanceTo to a later time. One flat list, not a list per
    // character: after a jump (a host starting at 30 s) every character has some, and a million small
    // lists cost the next frame 0.23 s to free (and glibc's consolidation of them).
    EarlierSegments earlier_;
    // earlier_'s segments of `character` (empty when it has none).
    std::span<const std::pair<std::uint32_t, Segment>> earlierOf(std::uint32_t character) const;
    double advancedFrom_ = 0.0;
    std::vector<gpu::MotionRecord> segments_;  // plans_ relative to epoch_
    std::vector<Agent> agents_;
    double plannedTo_ = 0.0;
    double epoch_ = 0.0;
    std::uint64_t planned_ = 0;
    std::vector<std::uint32_t> lastChanged_;
    std::vector<std::uint8_t> changed_;  // replanned in this advance (set by replan, cleared after)
    std::vector<std::uint32_t> added_;   // characters added since the last advance
    // A batch's per-entry results found on every core: spawns' wake times, whether a slot is new to
    // the change log's open generation.
    std::vector<double> batchWakes_;
    std::vector<std::uint8_t> batchFresh_;
    WakeCalendar calendar_;              // when each character's plan next runs out
    std::vector<std::uint32_t> due_;     // the characters this advance visits
    std::vector<double> dueWakes_;       // and when each next wakes, found beside its planning
    std::uint64_t generation_ = 0;
    // Key cursors of the sampling jobs, six per joint (two clips) per character: a cache of where each
    // track's keys were last found, private to the thread animating that character.
    mutable std::vector<std::uint16_t> cursors_;
    std::vector<std::uint64_t> cursorOffsets_;
};

}  // namespace crowd
