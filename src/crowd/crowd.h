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
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "anim/affine.h"
#include "anim/clip_library.h"
#include "crowd/behaviours.h"
#include "crowd/events.h"
#include "crowd/gaits.h"
#include "crowd/motion.h"
#include "crowd/rhythm.h"
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

class Crowd {
public:
    // The models must outlive the crowd. Throws gpu::Error when a character names a model or clip
    // that does not exist, or when there are more than MAX_MODELS models.
    Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters,
          const BehaviourSettings& behaviour = {});
    // A crowd of one model.
    Crowd(const model::SkinnedModel& model, std::vector<Character> characters, const BehaviourSettings& behaviour = {});

    std::uint32_t size() const { return static_cast<std::uint32_t>(characters_.size()); }
    const std::vector<Character>& characters() const { return characters_; }
    const std::vector<const model::SkinnedModel*>& models() const { return models_; }
    const model::SkinnedModel& model(std::uint32_t index) const { return *models_[index]; }
    const model::SkinnedModel& modelOf(std::uint32_t character) const { return *models_[characters_[character].model]; }
    // Every model's clips, flattened (the CPU jobs' input and what the GPU path uploads).
    const anim::ClipLibrary& library() const { return library_; }
    const Gaits& gaits(std::uint32_t model) const { return gaits_[model]; }
    const BehaviourSettings& behaviour() const { return behaviour_; }

    // ---- Driving the crowd ----
    // Adds a character playing its clip in place under the crowd's behaviour; returns its index.
    // Renderers size their buffers when they are made: spawn before making one.
    std::uint32_t spawn(const Character& character);
    // From time `at` on (or once its current crossfade ends), walk to `target` (world x, z) with clip
    // `gait` (-1: the model's walk) at `rate` times its speed, turning on the way, and stop there.
    void moveTo(std::uint32_t character, glm::vec2 target, double at, std::int32_t gait = -1, float rate = 1.0f);
    // From time `at` on, crossfade over `fade` seconds to `clip` at `rate` and keep playing it; a clip
    // with root motion carries the character forward along its heading. Throws gpu::Error for a clip the
    // model lacks (a negative one too: what SkinnedModel::findClip returns for a missing name).
    void play(std::uint32_t character, std::int32_t clip, double at, float fade = 0.3f, float rate = 1.0f);
    // Plans every character's segments up to `time`. A behaviour's character whose episode ended
    // goes straight to the episode holding `time` (its start is closed form), so a late time costs one
    // episode of planning, as an early one does. Going back in time starts every plan over from there
    // (commands given so far are forgotten).
    void advanceTo(double time);
    // The characters whose segment the last advanceTo (or command) changed, and a counter of those
    // calls, so a renderer can upload just them when it has seen every generation before.
    const std::vector<std::uint32_t>& lastChanged() const { return lastChanged_; }
    std::uint64_t generation() const { return generation_; }
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

    // Centre and radius of the ground the crowd stands on (and may walk over), and its tallest model's height.
    glm::vec3 center() const;
    float radius() const;
    float tallestHeight() const;

private:
    void addCharacter(const Character& character);
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
    void checkCharacter(std::uint32_t character) const;
    void command(std::uint32_t character, double at);
    PlanContext planContext(std::uint32_t character) const;

    std::vector<const model::SkinnedModel*> models_;
    std::vector<Character> characters_;
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
