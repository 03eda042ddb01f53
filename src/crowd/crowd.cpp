#include "crowd/crowd.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/soa_blending_job.h"
#include "anim/props_carried.h"
#include "anim/soa_palette_job.h"
#include "anim/soa_sampling_job.h"
#include "crowd/epoch.h"
#include "crowd/worker_pool.h"
#include "model/measure_root_motion.h"
#include "gpu/error.h"
#include "model/attach_prop.h"

namespace crowd {

std::uint32_t defaultClip(const model::SkinnedModel& model) {
    const int walk = model.findClip("walk");
    return walk >= 0 ? static_cast<std::uint32_t>(walk) : 0u;
}

float brightnessVariation(std::uint32_t index) {
    std::uint32_t h = index * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return 0.82f + 0.36f * static_cast<float>(h & 1023u) / 1023.0f;
}

namespace {

float widestFootprint(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options) {
    float widest = 0.0f;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const glm::vec3 extent = models[m]->boundsMax - models[m]->boundsMin;
        const float scale = m < options.scales.size() ? options.scales[m] : 1.0f;
        widest = std::max(widest, std::max(extent.x, extent.z) * scale);
    }
    return widest;
}

std::uint32_t clipFor(const model::SkinnedModel& model, std::uint32_t modelIndex, const LayoutOptions& options,
                      std::mt19937& random) {
    if (model.clips.empty()) return 0;
    if (options.randomClips) return static_cast<std::uint32_t>(random() % model.clips.size());
    const int clip = modelIndex < options.clips.size() ? options.clips[modelIndex] : -1;
    return clip >= 0 ? static_cast<std::uint32_t>(clip) : defaultClip(model);
}

}  // namespace

std::vector<Character> gridLayout(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options) {
    // Room for the widest side of any model plus a gap, so neighbours never intersect.
    const float spacing = widestFootprint(models, options) * 1.25f + 0.3f;
    const auto columns = std::max<std::uint32_t>(
        1u, static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(options.count) / options.depthRatio))));
    const auto rows = (options.count + columns - 1) / columns;
    std::vector<float> weights = options.weights;
    weights.resize(models.size(), weights.empty() ? 1.0f : 0.0f);

    std::mt19937 random(options.seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::discrete_distribution<std::uint32_t> pickModel(weights.begin(), weights.end());
    std::vector<Character> characters(options.count);
    for (std::uint32_t i = 0; i < options.count; ++i) {
        Character& c = characters[i];
        // One model keeps the random sequence of the single-model layout, so its crowds stay as they were.
        c.model = models.size() > 1 ? pickModel(random) : 0u;
        const model::SkinnedModel& model = *models[c.model];
        const float x = (static_cast<float>(i % columns) - 0.5f * static_cast<float>(columns - 1)) * spacing;
        const float z = (static_cast<float>(i / columns) - 0.5f * static_cast<float>(rows - 1)) * spacing;
        c.clip = clipFor(model, c.model, options, random);
        const float duration = model.clips.empty() ? 1.0f : model.clips[c.clip].duration;
        c.timeOffset = unit(random) * duration;
        c.speed = 0.9f + 0.2f * unit(random);
        c.position = glm::vec3(x + (unit(random) - 0.5f) * 0.15f * spacing, 0.0f,
                               z + (unit(random) - 0.5f) * 0.15f * spacing);
        c.heading = (unit(random) - 0.5f) * 0.5f;
        c.scale = c.model < options.scales.size() ? options.scales[c.model] : 1.0f;
        c.tint = glm::vec3(brightnessVariation(i));
        c.props = options.props ? model::defaultPropsCarried(*models[c.model], options.seed, i) : 0u;
        if (options.scaleVariation > 0.0f) c.scale *= 1.0f + options.scaleVariation * (2.0f * unit(random) - 1.0f);
        if (options.tintVariation > 0.0f)
            for (int k = 0; k < 3; ++k) c.tint[k] *= 1.0f + options.tintVariation * (2.0f * unit(random) - 1.0f);
        if (options.formation) {
            c.position = glm::vec3(x, 0.0f, z);
            c.heading = 0.0f;
            c.timeOffset = 0.0f;
            c.speed = 1.0f;
        }
    }
    return characters;
}

glm::mat4 characterTransform(const Character& character) {
    const glm::mat4 translate = glm::translate(glm::mat4(1.0f), character.position);
    const glm::mat4 turn = glm::rotate(translate, character.heading, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::scale(turn, glm::vec3(character.scale));
}

Crowd::Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters,
             const BehaviourSettings& behaviour)
    : models_(std::move(models)), behaviour_(behaviour) {
    if (models_.empty() || models_.size() > MAX_MODELS)
        throw gpu::Error("a crowd holds 1 to " + std::to_string(MAX_MODELS) + " models, not " +
                         std::to_string(models_.size()));
    for (const model::SkinnedModel* m : models_) {
        std::vector<anim::RootMotion> rootMotion;
        for (const anim::Clip& clip : m->clips) rootMotion.push_back(model::measureRootMotion(*m, clip));
        const std::uint32_t index = library_.addModel(m->skeleton, m->clips, rootMotion);
        gaits_.push_back(findGaits(*m, library_, index));
        rhythms_.push_back(measureRhythm(library_, index, gaits_.back(), behaviour_));
    }
    characters_.reserve(characters.size());
    for (const Character& c : characters) addCharacter(c);
}

Crowd::Crowd(const model::SkinnedModel& model, std::vector<Character> characters, const BehaviourSettings& behaviour)
    : Crowd(std::vector<const model::SkinnedModel*>{&model}, std::move(characters), behaviour) {}

void Crowd::addCharacter(const Character& c) {
    const auto index = static_cast<std::uint32_t>(characters_.size());
    if (c.model >= models_.size())
        throw gpu::Error("character " + std::to_string(index) + " names model " + std::to_string(c.model) + " of " +
                         std::to_string(models_.size()));
    const model::SkinnedModel& m = *models_[c.model];
    if (!m.clips.empty() && c.clip >= m.clips.size())
        throw gpu::Error("character " + std::to_string(index) + " names clip " + std::to_string(c.clip) + " of " +
                         m.name + ", which has " + std::to_string(m.clips.size()));
    characters_.push_back(c);
    Character& added = characters_.back();
    const std::uint32_t modelProps = (1u << m.props.size()) - 1u;  // props.size() <= MAX_PROPS < 32
    added.props = c.props == kModelProps ? model::defaultPropsCarried(m, behaviour_.seed, index) : c.props & modelProps;
    cursorOffsets_.push_back(cursors_.size());
    cursors_.resize(cursors_.size() + 6u * m.skeleton.jointCount(), 0u);
    // Phase and rate as the paper's crowd plays them: clip time = timeOffset + time x speed.
    const float duration = m.clips.empty() ? 0.0f : m.clips[c.clip].duration;
    const Segment first{0.0,
                        inPlaceSegment(library_, c.model, c.clip, c.position, c.heading, 0.0f,
                                       duration > 0.0f ? c.timeOffset / duration : 0.0f, c.speed),
                        exactCyclesPerSecond(library_, c.model, c.clip, c.speed)};
    agents_.emplace_back();
    plans_.push_back(startBehaviour(agents_.back(), first, planContext(index)));
    previous_.push_back(plans_.back());
    knownFrom_.push_back(-std::numeric_limits<double>::infinity());
    seal(plans_.back(), library_, c.model);
    segments_.push_back(recordFrom(plans_.back(), epoch_, library_, c.model));
    changed_.push_back(0u);
    lastChanged_.push_back(index);
    added_.push_back(index);
    calendar_.file(index, wakeOf(index));
    ++generation_;
}

std::uint32_t Crowd::spawn(const Character& character) {
    lastChanged_.clear();
    addCharacter(character);
    plannedTo_ = std::min(plannedTo_, 0.0);
    return size() - 1;
}

PlanContext Crowd::planContext(std::uint32_t character) const {
    const std::uint32_t model = characters_[character].model;
    return {library_, model, gaits_[model], behaviour_, rhythms_[model], character};
}

std::uint32_t Crowd::replan(std::uint32_t character, double time, EarlierSegments& earlier) {
    Agent& agent = agents_[character];
    // previous_ is about to be replaced; it held up to `end`. Kept when it is known and the window
    // since the last advance reaches into it.
    auto keepPrevious = [&](double end) {
        const Segment& old = previous_[character];
        if (!std::isinf(knownFrom_[character]) && knownFrom_[character] <= old.start && end > advancedFrom_)
            earlier.emplace_back(character, old);
    };
    const PlanContext context = planContext(character);
    const std::uint32_t model = characters_[character].model;
    std::uint32_t planned = 0;
    auto changed = [&] {
        seal(plans_[character], library_, model);
        changed_[character] = 1u;
        ++planned;
    };
    // Past the episode under way: straight to the one holding `time`, not through every one between
    // (what lies between is not known exactly: queries start at the new plan).
    const Segment before = plans_[character];
    const double beforeDue = agent.due, beforeEnd = agent.episodeEnd;
    if (skipTo(agent, time, context, plans_[character])) {
        changed();
        // The plan it replaced held up to the new one's start when neither its own end nor its
        // episode's came first (the next episode, entered as a frame reaches it); else the skipped
        // stretch is not known exactly.
        const double start = plans_[character].start;
        if (beforeDue >= start && beforeEnd >= start && before.start < start) {
            keepPrevious(before.start);
            previous_[character] = before;
            knownFrom_[character] = before.start;
        } else {
            knownFrom_[character] = start;
        }
    }
    while (agent.due <= time) {
        Segment next = planNext(agent, plans_[character], context);
        keepPrevious(plans_[character].start);
        previous_[character] = std::move(plans_[character]);
        plans_[character] = std::move(next);
        changed();
        knownFrom_[character] = previous_[character].start;
    }
    return planned;
}

double Crowd::wakeOf(std::uint32_t character) const {
    const Agent& agent = agents_[character];
    // A commanded character follows its commands only; a behaviour's also wakes when its episode ends.
    return agent.commanded ? agent.due : std::min(agent.due, agent.episodeEnd);
}

void Crowd::restateRecords() {
    // A new epoch restates every character (tens of nanoseconds each), else the changed ones: on every
    // core, as planning is, in chunks of 256 (a few microseconds), so that a frame's few thousand changed
    // ones spread over every core (chunks of 4096 gave them to one or two).
    WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(lastChanged_.size()), 256,
                                     [&](std::uint32_t begin, std::uint32_t end) {
                                         for (std::uint32_t i = begin; i < end; ++i) {
                                             const std::uint32_t c = lastChanged_[i];
                                             segments_[c] = recordFrom(plans_[c], epoch_, library_, characters_[c].model);
                                         }
                                     });
}

void Crowd::advanceTo(double time) {
    if (time < plannedTo_) {
        // Back in time: every plan starts over from the layout.
        std::vector<Character> characters = std::move(characters_);
        characters_.clear();
        plans_.clear();
        previous_.clear();
        knownFrom_.clear();
        earlier_.clear();
        segments_.clear();
        agents_.clear();
        cursors_.clear();
        cursorOffsets_.clear();
        changed_.clear();
        added_.clear();
        calendar_.clear();
        for (const Character& c : characters) addCharacter(c);
    }
    if (time > plannedTo_) {
        // The new window starts where the last ended: what only the last one needed is dropped.
        for (const auto& entry : earlier_) knownFrom_[entry.first] = previous_[entry.first].start;
        earlier_.clear();
        advancedFrom_ = plannedTo_;
    }
    plannedTo_ = time;
    const bool newEpoch = epochOf(time) != epoch_;
    // Nobody's plan runs out by `time` (an in-place crowd: never), nobody was added and the epoch
    // holds: no character to visit.
    if (time < calendar_.earliest() && added_.empty() && !newEpoch) {
        lastChanged_.clear();
        ++generation_;
        return;
    }
    // Only the characters whose plan runs out by `time` are visited. They plan independently (their
    // choices hash their own index), so any split of the work gives the same crowd.
    calendar_.takeDue(time, [this](std::uint32_t c) { return wakeOf(c); }, due_);
    dueWakes_.resize(due_.size());
    std::atomic<std::uint64_t> planned{0};
    std::mutex earlierLock;
    std::vector<EarlierSegments> earlier;  // a chunk's each
    // Chunks of 16: a replan takes microseconds, and a frame's few thousand due characters in chunks of
    // 64 left the last cores of 16 waiting on the slowest chunks. Each wake is found here too, on every
    // core, for the calendar to file below (one core's random reads of a million agents otherwise).
    WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(due_.size()), 16,
                                     [&](std::uint32_t begin, std::uint32_t end) {
                                         std::uint64_t count = 0;
                                         EarlierSegments mine;
                                         for (std::uint32_t i = begin; i < end; ++i) {
                                             count += replan(due_[i], time, mine);
                                             dueWakes_[i] = wakeOf(due_[i]);
                                         }
                                         planned.fetch_add(count, std::memory_order_relaxed);
                                         if (mine.empty()) return;
                                         const std::lock_guard<std::mutex> hold(earlierLock);
                                         earlier.push_back(std::move(mine));
                                     });
    planned_ += planned.load();
    keepEarlier(earlier);
    lastChanged_.clear();
    if (newEpoch) {
        epoch_ = epochOf(time);
        lastChanged_.resize(size());
        std::iota(lastChanged_.begin(), lastChanged_.end(), 0u);
    } else {
        for (const std::uint32_t c : due_)
            if (changed_[c]) lastChanged_.push_back(c);
        lastChanged_.insert(lastChanged_.end(), added_.begin(), added_.end());
        std::sort(lastChanged_.begin(), lastChanged_.end());
        lastChanged_.erase(std::unique(lastChanged_.begin(), lastChanged_.end()), lastChanged_.end());
    }
    for (std::size_t i = 0; i < due_.size(); ++i) {
        changed_[due_[i]] = 0u;
        calendar_.file(due_[i], dueWakes_[i]);
    }
    added_.clear();
    restateRecords();
    ++generation_;
}

void Crowd::keepEarlier(std::vector<EarlierSegments>& chunks) {
    // A chunk's segments come by character (due_ ascends), each one's in time order, and chunks cover
    // ranges of characters that do not overlap: sorted by their first character and joined, they keep
    // that order over the whole list.
    std::sort(chunks.begin(), chunks.end(),
              [](const EarlierSegments& a, const EarlierSegments& b) { return a.front().first < b.front().first; });
    const bool more = !earlier_.empty();  // a second advance to the same time
    for (const EarlierSegments& chunk : chunks) earlier_.insert(earlier_.end(), chunk.begin(), chunk.end());
    if (more)
        std::stable_sort(earlier_.begin(), earlier_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < earlier_.size(); ++i)
        if (i == 0 || earlier_[i].first != earlier_[i - 1].first) knownFrom_[earlier_[i].first] = earlier_[i].second.start;
}

std::span<const std::pair<std::uint32_t, Segment>> Crowd::earlierOf(std::uint32_t character) const {
    const auto first = std::lower_bound(earlier_.begin(), earlier_.end(), character,
                                        [](const auto& entry, std::uint32_t c) { return entry.first < c; });
    auto last = first;
    while (last != earlier_.end() && last->first == character) ++last;
    return {first, last};
}

void Crowd::checkCharacter(std::uint32_t character) const {
    if (character >= size())
        throw gpu::Error("no character " + std::to_string(character) + " in a crowd of " + std::to_string(size()));
}

void Crowd::command(std::uint32_t character, double at) {
    Agent& agent = agents_[character];
    const Segment& current = plans_[character];
    // A crossfade in progress finishes first: a segment blends two clips, never three.
    agent.due = std::max(at, current.start + current.motion.timing.y);
    agent.commanded = true;
    calendar_.file(character, wakeOf(character));
}

// Commands check everything before they change anything: a refused one leaves the character as it was.
void Crowd::moveTo(std::uint32_t character, glm::vec2 target, double at, std::int32_t gait, float rate) {
    checkCharacter(character);
    const std::uint32_t model = characters_[character].model;
    const std::int32_t clip = gait >= 0 ? gait : gaits_[model].walk;
    if (clip < 0 || static_cast<std::uint32_t>(clip) >= library_.clipCount(model) ||
        glm::length(library_.stride(model, static_cast<std::uint32_t>(clip))) == 0.0f)
        throw gpu::Error("character " + std::to_string(character) + ": " + modelOf(character).name +
                         " has no clip " + (gait >= 0 ? std::to_string(gait) + " " : std::string()) +
                         "that travels to use as its gait");
    command(character, at);
    Agent& agent = agents_[character];
    agent.gait = clip;
    agent.target = target;
    agent.rate = rate;
    agent.stage = Agent::Stage::Stand;
}

void Crowd::play(std::uint32_t character, std::int32_t clip, double at, float fade, float rate) {
    checkCharacter(character);
    if (clip < 0 || static_cast<std::uint32_t>(clip) >= library_.clipCount(characters_[character].model))
        throw gpu::Error("character " + std::to_string(character) + ": " + modelOf(character).name + " has no clip " +
                         std::to_string(clip));
    command(character, at);
    Agent& agent = agents_[character];
    agent.gait = clip;
    agent.rate = rate;
    agent.fade = fade;
    agent.stage = Agent::Stage::Play;
}

MotionState Crowd::stateAt(std::uint32_t index, double time) const {
    return evaluateMotion(segments_[index], static_cast<float>(time - epoch_), library_, characters_[index].model);
}

MotionState Crowd::stateKnown(std::uint32_t index, double time) const {
    checkCharacter(index);
    if (!(time >= knownFrom_[index]))
        throw gpu::Error("character " + std::to_string(index) + ": time " + std::to_string(time) +
                         " s is before " + std::to_string(knownFrom_[index]) +
                         " s, the earliest its plans still hold (query each frame's window as you advance)");
    const std::uint32_t model = characters_[index].model;
    if (time >= plans_[index].start || std::isinf(knownFrom_[index])) return stateAt(index, time);
    const Segment* segment = &previous_[index];
    if (time < previous_[index].start)
        for (const auto& [character, s] : earlierOf(index))
            if (s.start <= time) segment = &s;
    return evaluateMotion(recordFrom(*segment, epoch_, library_, model), static_cast<float>(time - epoch_), library_,
                          model);
}

template <class F>
void Crowd::forEachKnownSegment(std::uint32_t index, F&& f) const {
    const Segment& current = plans_[index];
    double previousFrom = knownFrom_[index];
    if (const auto list = earlierOf(index); !list.empty()) {
        for (std::size_t i = 0; i < list.size(); ++i)
            f(list[i].second, list[i].second.start,
              i + 1 < list.size() ? list[i + 1].second.start : previous_[index].start);
        previousFrom = previous_[index].start;
    }
    if (!std::isinf(knownFrom_[index]) && previousFrom < current.start) f(previous_[index], previousFrom, current.start);
    f(current, current.start, std::numeric_limits<double>::infinity());
}

anim::Affine Crowd::jointWorld(std::uint32_t index, std::uint32_t joint, double time) const {
    checkCharacter(index);
    const std::uint32_t joints = library_.jointCount(characters_[index].model);
    if (joint >= joints)
        throw gpu::Error("character " + std::to_string(index) + ": " + modelOf(index).name + " has no joint " +
                         std::to_string(joint) + " (it has " + std::to_string(joints) + ")");
    thread_local std::vector<gpu::BoneRows> palette;
    thread_local std::vector<anim::Affine> world;
    palette.resize(joints);
    world.resize(joints);
    animateState(index, stateKnown(index, time), palette, world);
    return world[joint];
}

void Crowd::events(std::span<const std::uint32_t> characters, double from, double to, EventSink& out) const {
    for (const std::uint32_t c : characters) {
        checkCharacter(c);
        if (!(from >= knownFrom_[c]))
            throw gpu::Error("character " + std::to_string(c) + ": events from " + std::to_string(from) +
                             " s asked, but its plans hold from " + std::to_string(knownFrom_[c]) +
                             " s on (ask for each frame's window as you advance)");
        const std::uint32_t model = characters_[c].model;
        forEachKnownSegment(c, [&](const Segment& segment, double begin, double end) {
            segmentEvents(segment, *models_[model], library_, model, c, begin, end, from, to, out);
        });
    }
}

void Crowd::poseRecord(std::uint32_t index, double time, gpu::CharacterRecord& record) const {
    writePose(stateAt(index, time), record);
}

void Crowd::writePose(const MotionState& state, gpu::CharacterRecord& record) {
    record.placement = glm::vec4(state.position, state.heading);
    record.ids.w = state.clipFrom | (state.clipTo << 16);
    record.pose.x = state.phase;  // z, the props carried, is the character's for good (crowd_buffers.cpp)
    record.pose.y = state.weight;
}

void Crowd::animateCharacter(std::uint32_t index, double time, std::span<gpu::BoneRows> out) const {
    animateState(index, stateAt(index, time), out);
}

void Crowd::animateState(std::uint32_t index, const MotionState& state, std::span<gpu::BoneRows> out,
                         std::span<anim::Affine> world) const {
    const Character& c = characters_[index];
    const std::uint32_t joints = library_.jointCount(c.model);
    // Per-thread scratch, reused by the pool's long-lived threads: once warm, animation allocates nothing.
    // Poses are structure of arrays, four joints a group: the SoA jobs run four joints per instruction
    // and give the scalar jobs' bones (tests/test_soa_jobs.cpp).
    thread_local std::vector<anim::SoaTransform> from, to;
    thread_local std::vector<anim::Affine> modelSpace;
    from.resize(anim::soaGroups(joints));
    to.resize(anim::soaGroups(joints));
    modelSpace.resize(joints);
    std::span<std::uint16_t> cursors(cursors_.data() + cursorOffsets_[index], 6u * joints);
    if (library_.clipCount(c.model) == 0) {
        anim::toSoa(models_[c.model]->skeleton.restPose, to);
    } else {
        // Both clips at the same point of their cycles (synchronized phase).
        const float cycle = state.phase - std::floor(state.phase);
        auto sample = [&](std::uint32_t clip, std::span<std::uint16_t> clipCursors, std::vector<anim::SoaTransform>& pose) {
            anim::SoaSamplingJob{&library_, c.model, clip, cycle * library_.duration(c.model, clip), clipCursors, pose}.run();
        };
        sample(state.clipTo, cursors.subspan(3u * joints), to);
        if (state.weight < 1.0f) {
            sample(state.clipFrom, cursors.first(3u * joints), from);
            anim::SoaBlendingJob{from, to, state.weight, to}.run();
        }
    }
    const anim::Affine placement = anim::placementAffine(state.position, state.heading, c.scale);
    const std::span<anim::Affine> worldOut = world.empty() ? std::span<anim::Affine>(modelSpace) : world;
    anim::SoaPaletteJob{&library_, c.model, placement, to, worldOut, out.first(joints)}.run();
    anim::collapseUncarriedProps(models_[c.model]->skeleton.propOfJoint, c.props, worldOut, out.first(joints));
}

void Crowd::animate(double time, std::span<gpu::BoneRows> out, std::span<const std::uint32_t> boneOffsets,
                    std::span<gpu::CharacterRecord> records, WorkerPool* pool) const {
    // Chunks of 32 characters (tens of microseconds each) keep the handoff cost small and the cores even.
    (pool ? *pool : WorkerPool::shared()).parallelFor(size(), 32, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) {
            // The motion is evaluated once for both the bones and the record.
            const MotionState state = stateAt(i, time);
            animateState(i, state, out.subspan(boneOffsets[i]));
            if (!records.empty()) writePose(state, records[i]);
        }
    });
}

glm::vec3 Crowd::center() const {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Character& c : characters_) lo = glm::min(lo, c.position), hi = glm::max(hi, c.position);
    if (characters_.empty()) return glm::vec3(0.0f);
    // A formation marches out along +z and back: the middle of its beat.
    if (behaviour_.kind == Behaviour::March) hi.z += behaviour_.marchLength;
    return 0.5f * (lo + hi);
}

float Crowd::radius() const {
    const glm::vec3 mid = center();
    float r = 0.0f, widest = 0.0f;
    for (const Character& c : characters_) r = std::max(r, glm::length(c.position - mid));
    for (const model::SkinnedModel* m : models_) {
        const glm::vec3 extent = m->boundsMax - m->boundsMin;
        widest = std::max(widest, std::max(extent.x, extent.z));
    }
    // Characters that move stay within their behaviour's reach of where they started.
    float reach = 0.0f;
    if (behaviour_.kind == Behaviour::Mill) reach = behaviour_.millRadius + 1.0f;
    if (behaviour_.kind == Behaviour::March) reach = 2.0f;  // the centre already spans its beat
    return r + 0.5f * widest + reach;
}

float Crowd::tallestHeight() const {
    float tallest = 0.0f;
    for (const Character& c : characters_) tallest = std::max(tallest, models_[c.model]->height() * c.scale);
    return characters_.empty() ? models_[0]->height() : tallest;
}

}  // namespace crowd
