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
#include "crowd/driven_events.h"
#include "crowd/driven_rules.h"
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

namespace {

// The model of every slot: the characters' own, then each model's spare slots in model order.
std::vector<std::uint32_t> slotModels(const std::vector<Character>& characters, std::size_t models,
                                      const Capacity& capacity) {
    std::vector<std::uint32_t> result;
    std::vector<std::uint64_t> initial(models, 0);
    for (std::size_t i = 0; i < characters.size(); ++i) {
        const std::uint32_t m = characters[i].model;
        if (m >= models)
            throw gpu::Error("character " + std::to_string(i) + " names model " + std::to_string(m) + " of " +
                             std::to_string(models));
        result.push_back(m);
        ++initial[m];
    }
    std::uint64_t total = result.size();
    for (std::size_t m = 0; m < models && m < capacity.perModel.size(); ++m)
        total += capacity.perModel[m] > initial[m] ? capacity.perModel[m] - initial[m] : 0u;
    if (total > 0xFFFFFFFFull)
        throw gpu::Error("a crowd of " + std::to_string(total) + " slots: at most 4,294,967,295", gpu::ErrorKind::InvalidArgument);
    for (std::size_t m = 0; m < models && m < capacity.perModel.size(); ++m)
        for (std::uint64_t k = initial[m]; k < capacity.perModel[m]; ++k) result.push_back(static_cast<std::uint32_t>(m));
    return result;
}

std::uint64_t nextCrowdId() {
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

// FNV-1a over the models' addresses and every slot's model.
std::uint64_t layoutKeyOf(const std::vector<const model::SkinnedModel*>& models, const std::vector<Character>& slots) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](std::uint64_t v) {
        for (int b = 0; b < 8; ++b) h = (h ^ ((v >> (8 * b)) & 0xFFu)) * 1099511628211ull;
    };
    for (const model::SkinnedModel* m : models) mix(reinterpret_cast<std::uintptr_t>(m));
    mix(slots.size());
    for (const Character& c : slots) mix(c.model);
    return h;
}

}  // namespace

Crowd::Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters,
             const BehaviourSettings& behaviour, const Capacity& capacity)
    : models_(std::move(models)),
      population_({}, 0, 0),
      id_(nextCrowdId()),
      behaviour_(behaviour) {
    if (models_.empty() || models_.size() > MAX_MODELS)
        throw gpu::Error("a crowd holds 1 to " + std::to_string(MAX_MODELS) + " models, not " +
                         std::to_string(models_.size()));
    for (const model::SkinnedModel* m : models_) {
        std::vector<anim::RootMotion> rootMotion;
        for (const anim::Clip& clip : m->clips) rootMotion.push_back(model::measureRootMotion(*m, clip));
        const std::uint32_t index = library_.addModel(m->skeleton, m->clips, rootMotion);
        gaits_.push_back(findGaits(*m, library_, index));
        rhythms_.push_back(measureRhythm(library_, index, gaits_.back(), behaviour_));
        bands_.push_back(defaultGaitBands(library_, index, gaits_.back()));
        drivenModels_.push_back(drivenModel(library_, index, gaits_.back(), bands_.back()));
    }
    if (capacity.drivenKeys > kMostDrivenKeys)
        throw gpu::Error("driven keys: " + std::to_string(capacity.drivenKeys) + " a slot, at most " +
                         std::to_string(kMostDrivenKeys));
    const bool anyDriven = std::any_of(characters.begin(), characters.end(),
                                       [](const Character& c) { return c.driven != Driven::No; });
    drivenKeysPerSlot_ = capacity.drivenKeys != 0 ? capacity.drivenKeys : anyDriven ? kDefaultDrivenKeys : 0u;
    const std::vector<std::uint32_t> models_of = slotModels(characters, models_.size(), capacity);
    const auto initial = static_cast<std::uint32_t>(characters.size());
    for (std::uint32_t i = 0; i < initial; ++i)
        if (const std::string problem = characterProblem(characters[i]); !problem.empty())
            throw gpu::Error("character " + std::to_string(i) + " " + problem);
    population_ = Population(models_of, initial, static_cast<std::uint32_t>(models_.size()));
    characters_ = std::move(characters);
    // A spare slot holds its model's default character until a spawn gives it one.
    for (std::uint32_t s = initial; s < models_of.size(); ++s) {
        Character spare;
        spare.model = models_of[s];
        spare.clip = models_[spare.model]->clips.empty() ? 0u : defaultClip(*models_[spare.model]);
        characters_.push_back(spare);
    }
    layoutKey_ = layoutKeyOf(models_, characters_);
    const std::uint32_t slots = size();
    changes_ = ChangeLog(slots);
    plans_.resize(slots);
    previous_.resize(slots);
    knownFrom_.assign(slots, -std::numeric_limits<double>::infinity());
    bornAt_.assign(slots, -std::numeric_limits<double>::infinity());
    segments_.resize(slots);
    agents_.resize(slots);
    changed_.assign(slots, 0u);
    cursorOffsets_.reserve(slots);
    for (std::uint32_t s = 0; s < slots; ++s) {
        cursorOffsets_.push_back(cursors_.size());
        cursors_.resize(cursors_.size() + 6u * models_[characters_[s].model]->skeleton.jointCount(), 0u);
    }
    for (std::uint32_t s = 0; s < slots; ++s) {
        if (population_.alive(s)) {
            startSlot(s);
        } else {
            // Free: a record in place at the origin (culling skips the slot: its identity's scale is 0).
            segments_[s] = inPlaceSegment(library_, characters_[s].model, characters_[s].clip, glm::vec3(0.0f), 0.0f,
                                          0.0f, 0.0f, 0.0f);
            plans_[s] = previous_[s] = Segment{0.0, segments_[s], 0.0};
        }
    }
}

Crowd::Crowd(const model::SkinnedModel& model, std::vector<Character> characters, const BehaviourSettings& behaviour)
    : Crowd(std::vector<const model::SkinnedModel*>{&model}, std::move(characters), behaviour) {}

std::string Crowd::characterProblem(const Character& c) const {
    if (c.model >= models_.size()) return "names model " + std::to_string(c.model) + " of " + std::to_string(models_.size());
    const model::SkinnedModel& m = *models_[c.model];
    if (!m.clips.empty() && c.clip >= m.clips.size())
        return "names clip " + std::to_string(c.clip) + " of " + m.name + ", which has " + std::to_string(m.clips.size());
    if (c.driven != Driven::No && drivenKeysPerSlot_ == 0)
        return "is driven, but the crowd was made without driven keys (give its capacity's drivenKeys)";
    return {};
}

void Crowd::startSlot(std::uint32_t index) {
    planSlot(index);
    noteStarted(index);
}

void Crowd::planSlot(std::uint32_t index) {
    Character& c = characters_[index];
    if (!keys_.empty()) keys_.clear(index);
    const model::SkinnedModel& m = *models_[c.model];
    const std::uint32_t modelProps = (1u << m.props.size()) - 1u;  // props.size() <= MAX_PROPS < 32
    c.props = c.props == kModelProps ? model::defaultPropsCarried(m, behaviour_.seed, index) : c.props & modelProps;
    // The slot's sampling cursors stay as they were: they are hints, and sampling gives the same pose
    // whatever they hold (tests/test_living_crowd.cpp), so a spawn need not clear its ten cache lines.
    // Phase and rate as the paper's crowd plays them: clip time = timeOffset + time x speed.
    const float duration = m.clips.empty() ? 0.0f : m.clips[c.clip].duration;
    const Segment first{0.0,
                        inPlaceSegment(library_, c.model, c.clip, c.position, c.heading, 0.0f,
                                       duration > 0.0f ? c.timeOffset / duration : 0.0f, c.speed),
                        exactCyclesPerSecond(library_, c.model, c.clip, c.speed)};
    agents_[index] = Agent{};
    // A driven character holds its place, in place, until its first key; nothing plans it.
    plans_[index] = c.driven == Driven::No ? startBehaviour(agents_[index], first, planContext(index)) : first;
    if (c.driven != Driven::No)
        plans_[index].motion.phase.w = c.driven == Driven::HostSamples ? MOTION_DRIVEN_HOST : MOTION_DRIVEN_DEVICE;
    previous_[index] = plans_[index];
    knownFrom_[index] = -std::numeric_limits<double>::infinity();
    seal(plans_[index], library_, c.model);
    segments_[index] = recordFrom(plans_[index], epoch_, library_, c.model);
    changed_[index] = 0u;
}

void Crowd::noteStarted(std::uint32_t index) {
    lastChanged_.push_back(index);
    added_.push_back(index);
    changes_.mark(index);
    calendar_.file(index, wakeOf(index));
}

template <class F>
void Crowd::forEachOfBatch(std::size_t count, const F& f) {
    const auto run = [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) f(i);
    };
    // Below a few hundred the workers' wake-up costs more than the batch.
    if (count < 256) run(0, static_cast<std::uint32_t>(count));
    else WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(count), 64, run);
}

Handle Crowd::spawn(const Character& character) {
    Handle handle;
    spawn(&character, 1, &handle);
    return handle;
}

void Crowd::spawn(const Character* characters, std::size_t count, Handle* handles) {
    std::vector<std::uint32_t> wanted(models_.size(), 0u);
    for (std::size_t i = 0; i < count; ++i) {
        if (const std::string problem = characterProblem(characters[i]); !problem.empty())
            throw gpu::Error("spawn: " +
                             (count > 1 ? "character " + std::to_string(i) + " of the batch " : "the character ") + problem);
        ++wanted[characters[i].model];
    }
    for (std::uint32_t m = 0; m < wanted.size(); ++m)
        if (wanted[m] > population_.freeOf(m))
            throw gpu::Error(
                "spawn: " +
                    (count > 1 ? "a batch of " + std::to_string(count) + " needs " + std::to_string(wanted[m]) +
                                     " slots for model " + std::to_string(m) + " (" + models_[m]->name + "), and " +
                                     std::to_string(population_.freeOf(m)) + " of the crowd's " +
                                     std::to_string(population_.capacityOf(m)) + " are free (the others taken: "
                               : "every one of the crowd's " + std::to_string(population_.capacityOf(m)) +
                                     " slots for model " + std::to_string(m) + " (" + models_[m]->name + ") is taken (") +
                    "its capacity, fixed when the crowd was made)",
                             gpu::ErrorKind::CapacityExceeded);
    // One core pops the free lists (sequential reads); every slot's own state, its planning and its wake
    // are written on every core (random writes: a spawn is a few cache misses, shared by the cores);
    // one core appends the slots to the lists every slot shares.
    for (std::size_t i = 0; i < count; ++i) handles[i].slot = population_.popFree(characters[i].model);
    batchWakes_.resize(count);
    batchFresh_.resize(count);
    forEachOfBatch(count, [&](std::size_t i) {
        const std::uint32_t slot = handles[i].slot;
        handles[i].generation = population_.admit(slot);
        characters_[slot] = characters[i];
        planSlot(slot);
        bornAt_[slot] = plannedTo_;
        batchWakes_[i] = wakeOf(slot);
        batchFresh_[i] = changes_.claim(slot);
    });
    population_.admitted(static_cast<std::uint32_t>(count));
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t slot = handles[i].slot;
        lastChanged_.push_back(slot);
        added_.push_back(slot);
        if (batchFresh_[i]) changes_.list(slot);
        calendar_.file(slot, batchWakes_[i]);
    }
}

void Crowd::checkHandle(Handle handle) const {
    if (!population_.valid(handle)) throw gpu::Error(population_.whyInvalid(handle));
}

void Crowd::remove(Handle handle) { remove(&handle, 1); }

void Crowd::remove(const Handle* handles, std::size_t count) {
    // Checked whole first; a handle given twice is found as the population releases it the second time.
    for (std::size_t i = 0; i < count; ++i) checkHandle(handles[i]);
    for (std::size_t i = 0; i < count; ++i) {
        if (!population_.valid(handles[i])) {
            for (std::size_t j = i; j-- > 0;) population_.restore(handles[j]);  // the free lists unwound
            throw gpu::Error("remove: " + population_.name(handles[i]) + " is given twice in the batch");
        }
        population_.release(handles[i].slot);
    }
    // Nothing plans them any more (a stale calendar entry wakes nobody: wakeOf is never).
    batchFresh_.resize(count);
    forEachOfBatch(count, [&](std::size_t i) {
        agents_[handles[i].slot] = Agent{};
        batchFresh_[i] = changes_.claim(handles[i].slot);
    });
    for (std::size_t i = 0; i < count; ++i)
        if (batchFresh_[i]) changes_.list(handles[i].slot);
}

// ---- Driven characters ----

namespace {

MotionState drivenMotionState(const driven::DrivenPose& pose, const gpu::DrivenModel& model) {
    MotionState state;
    state.position = glm::vec3(pose.position.x, 0.0f, pose.position.y);
    state.heading = pose.heading;
    const glm::uvec2 clips = driven::drivenClips(pose.gait, model);
    state.clipFrom = clips.x;
    state.clipTo = clips.y;
    state.weight = pose.gait - driven::drivenLevel(pose.gait);
    state.phase = pose.phase;
    return state;
}

}  // namespace

std::uint64_t Crowd::sealChanges() const {
    const std::uint64_t sealed = changes_.seal();
    keyLog_.push_back(std::move(keyLogOpen_));
    keyLogOpen_.clear();
    while (keyLog_.size() > ChangeLog::kKeptGenerations) {
        keyLogOpen_ = std::move(keyLog_.front());  // its memory reused: a million keys a frame allocate nothing
        keyLogOpen_.clear();
        keyLog_.pop_front();
        ++keyLogFirst_;
    }
    return sealed;
}

const Crowd::KeyLogList& Crowd::keyLogOf(std::uint64_t generation) const {
    return generation == changes_.openGeneration() ? keyLogOpen_ : keyLog_[generation - keyLogFirst_ - 1];
}

std::size_t Crowd::keysSince(std::uint64_t since) const {
    if (since == ChangeLog::kEverything || since < keyLogFirst_) return std::size_t{size()} * drivenKeysPerSlot_;
    std::size_t total = 0;
    for (std::uint64_t g = since + 1; g <= changes_.openGeneration(); ++g) total += keyLogOf(g).size();
    return total;
}

float Crowd::drivenClock(double time) const { return static_cast<float>(time - epoch_ - timing_.delay); }

void Crowd::setDrivenTiming(const DrivenTiming& timing) {
    if (!(timing.delay >= 0.0 && timing.delay <= 3600.0) || !(timing.extrapolate >= 0.0 && timing.extrapolate <= 3600.0))
        throw gpu::Error("driven timing: delay " + std::to_string(timing.delay) + " s and extrapolation " +
                         std::to_string(timing.extrapolate) + " s must be 0 to 3,600 s");
    timing_ = timing;
}

void Crowd::setGaitBands(std::uint32_t model, const GaitBands& bands) {
    if (model >= models_.size())
        throw gpu::Error("gait bands: no model " + std::to_string(model) + " (the crowd has " +
                         std::to_string(models_.size()) + ")");
    const bool finite = std::isfinite(bands.walkFrom) && std::isfinite(bands.runFrom) && std::isfinite(bands.hysteresis) &&
                        std::isfinite(bands.fade) && std::isfinite(bands.turnRate) && std::isfinite(bands.turnSpeed);
    if (!finite || !(bands.walkFrom >= 0.0f) || !(bands.runFrom > bands.walkFrom) || !(bands.hysteresis >= 0.0f) ||
        !(bands.hysteresis < 1.0f) || !(bands.fade >= 0.0f) || !(bands.turnRate > 0.0f) || !(bands.turnSpeed >= 0.0f))
        throw gpu::Error("gait bands of model " + std::to_string(model) +
                         ": walk from >= 0 m/s, run from above it, hysteresis 0 to 1, fade >= 0 s, turn rate > 0, "
                         "turn speed >= 0 (all finite)");
    bands_[model] = bands;
    drivenModels_[model] = drivenModel(library_, model, gaits_[model], bands);
}

void Crowd::checkKnowable(std::uint32_t character) const {
    if (characters_[character].driven == Driven::DeviceSamples)
        throw gpu::Error("character " + std::to_string(character) +
                             " is driven by a device buffer: its motion is the GPU's alone (the CPU never sees its samples)",
                         gpu::ErrorKind::Unsupported);
}

void Crowd::startDriving(std::uint32_t slot) {
    // It holds its place and pose (in place, its clip at its phase) until its first key is drawn.
    const MotionState now = flatStateAt(slot, plannedTo_);
    const std::uint32_t model = characters_[slot].model;
    characters_[slot].driven = Driven::HostSamples;
    agents_[slot] = Agent{};
    Segment hold{plannedTo_,
                 inPlaceSegment(library_, model, now.clipTo, now.position, now.heading, 0.0f, now.phase, 0.0f), 0.0};
    hold.motion.phase.w = MOTION_DRIVEN_HOST;
    previous_[slot] = plans_[slot];
    knownFrom_[slot] = std::isinf(knownFrom_[slot]) ? knownFrom_[slot] : plans_[slot].start;
    plans_[slot] = hold;
    segments_[slot] = recordFrom(hold, epoch_, library_, model);
}

bool Crowd::checkBatch(const SampleBatch& batch) const {
    const std::size_t n = batch.characters.size();
    if (batch.times.size() != n || batch.x.size() != n || batch.z.size() != n || (!batch.headings.empty() && batch.headings.size() != n))
        throw gpu::Error("drive: the batch's arrays differ in length (" + std::to_string(n) + " characters, " +
                         std::to_string(batch.times.size()) + " times, " + std::to_string(batch.x.size()) + " x, " +
                         std::to_string(batch.z.size()) + " z, " + std::to_string(batch.headings.size()) + " headings)");
    if (n > 0 && drivenKeysPerSlot_ == 0)
        throw gpu::Error("drive: the crowd was made without driven keys (give its capacity's drivenKeys)");
    // The first bad entry, found on every core; its message is made once.
    std::atomic<std::size_t> firstBad{n};
    std::atomic<bool> behaviours{false};
    WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(n), 4096, [&](std::uint32_t begin, std::uint32_t end) {
        bool behaviour = false;
        for (std::uint32_t i = begin; i < end && i < firstBad.load(std::memory_order_relaxed); ++i) {
            const Handle h = batch.characters[i];
            const bool ok = population_.valid(h) && characters_[h.slot].driven != Driven::DeviceSamples &&
                            std::isfinite(batch.times[i]) && std::isfinite(batch.x[i]) && std::isfinite(batch.z[i]) &&
                            (batch.headings.empty() || !std::isinf(batch.headings[i])) && std::abs(batch.times[i]) <= 1e12;
            if (ok) {
                behaviour = behaviour || characters_[h.slot].driven == Driven::No;
                continue;
            }
            std::size_t seen = firstBad.load();
            while (i < seen && !firstBad.compare_exchange_weak(seen, i)) {}
            break;
        }
        if (behaviour) behaviours.store(true, std::memory_order_relaxed);
    });
    const std::size_t i = firstBad.load();
    if (i == n) return behaviours.load();
    const Handle h = batch.characters[i];
    const std::string where = "drive: sample " + std::to_string(i) + " (character " + std::to_string(h.slot) + ")";
    if (!population_.valid(h)) throw gpu::Error(where + ": " + population_.whyInvalid(h));
    if (characters_[h.slot].driven == Driven::DeviceSamples)
        throw gpu::Error(where + ": driven by a device buffer, not by samples from the host's memory");
    throw gpu::Error(where + ": time " + std::to_string(batch.times[i]) + ", position (" + std::to_string(batch.x[i]) +
                     ", " + std::to_string(batch.z[i]) + ")" +
                     (batch.headings.empty() ? std::string() : ", heading " + std::to_string(batch.headings[i])) +
                     ": times and positions must be finite (times within 1e12 s), a heading a number or NaN");
}

void Crowd::applySample(std::size_t i, const SampleBatch& batch, std::size_t& late) {
    const std::uint32_t slot = batch.characters[i].slot;
    const double time = batch.times[i];
    const std::uint32_t count = keys_.count(slot);
    if (count > 0 && !(time > keySceneTime(keys_.key(slot, count - 1)))) {
        ++late;
        return;
    }
    const double epochIndex = std::floor(time / kEpochSeconds);
    const auto clock = static_cast<float>(time - epochIndex * kEpochSeconds);
    const float heading = batch.headings.empty() ? std::numeric_limits<float>::quiet_NaN() : batch.headings[i];
    const gpu::DrivenKey previous = count > 0 ? keys_.key(slot, count - 1) : gpu::DrivenKey{};
    gpu::DrivenKey key = driven::drivenKeyAfter(previous, count == 0, clock, static_cast<float>(epochIndex),
                                                glm::vec2(batch.x[i], batch.z[i]), heading,
                                                drivenModels_[population_.modelOf(slot)]);
    // A first key with no heading given faces where the character faced.
    if (count == 0 && std::isnan(heading)) key.place.w = flatStateAt(slot, plannedTo_).heading;
    keys_.push(slot, key);
}

DriveResult Crowd::drive(const SampleBatch& batch) {
    const bool behaviours = checkBatch(batch);
    const std::size_t n = batch.characters.size();
    DriveResult result;
    if (n == 0) return result;
    if (keys_.empty()) keys_ = DrivenKeys(size(), drivenKeysPerSlot_);
    if (batchStamps_.empty()) batchStamps_.assign(size(), 0u);
    // Characters of the behaviour become driven at their first sample (serially: few, and rare).
    if (behaviours)
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t slot = batch.characters[i].slot;
            if (characters_[slot].driven != Driven::No) continue;
            startDriving(slot);
            changes_.mark(slot);
        }
    // A batch with one sample per character applies on every core; one with several of a character, in order.
    if (++batch_ == 0) std::fill(batchStamps_.begin(), batchStamps_.end(), 0u), batch_ = 1;
    std::atomic<bool> repeats{false};
    WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(n), 8192, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i)
            if (std::atomic_ref<std::uint32_t>(batchStamps_[batch.characters[i].slot]).exchange(batch_) == batch_)
                repeats.store(true, std::memory_order_relaxed);
    });
    // A host that records no frames (no renderer, or one far behind) would grow the open key log without
    // end: past every key the slots hold, sealing it costs a late renderer nothing (it uploads every key).
    if (keyLogOpen_.size() + n > std::size_t{size()} * drivenKeysPerSlot_) sealChanges();
    // The key log in the batch's order, each entry written by the thread that made its key (a renderer
    // uploads these keys, their slots' head counts with them); a late sample's entry is kNoKeySlot.
    const std::size_t logged = keyLogOpen_.size();
    keyLogOpen_.resize(logged + n);
    std::atomic<std::size_t> late{0};
    std::mutex reachLock;
    glm::vec2 lo(1e30f), hi(-1e30f);  // where the samples reach, for the crowd's bounds
    auto apply = [&](std::uint32_t begin, std::uint32_t end) {
        std::size_t lateHere = 0;
        glm::vec2 loHere(1e30f), hiHere(-1e30f);
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::size_t before = lateHere;
            applySample(i, batch, lateHere);
            const std::uint32_t slot = batch.characters[i].slot;
            keyLogOpen_[logged + i] = lateHere == before ? KeyLogEntry(slot, keys_.count(slot) - 1u) : KeyLogEntry(kNoKeySlot, 0u);
            loHere = glm::min(loHere, glm::vec2(batch.x[i], batch.z[i]));
            hiHere = glm::max(hiHere, glm::vec2(batch.x[i], batch.z[i]));
        }
        late.fetch_add(lateHere, std::memory_order_relaxed);
        const std::lock_guard<std::mutex> hold(reachLock);
        lo = glm::min(lo, loHere), hi = glm::max(hi, hiHere);
    };
    if (repeats.load())
        apply(0, static_cast<std::uint32_t>(n));
    else
        WorkerPool::shared().parallelFor(static_cast<std::uint32_t>(n), 4096, apply);
    result.late = late.load();
    result.applied = n - result.late;
    const glm::vec3 lo3(lo.x, 0.0f, lo.y), hi3(hi.x, 0.0f, hi.y);
    if (glm::any(glm::lessThan(lo3, drivenReach_.lo)) || glm::any(glm::greaterThan(hi3, drivenReach_.hi))) {
        drivenReach_.lo = glm::min(drivenReach_.lo, lo3);
        drivenReach_.hi = glm::max(drivenReach_.hi, hi3);
        ++reachVersion_;
    }
    return result;
}

MotionState Crowd::drivenState(std::uint32_t slot, double time) const {
    const std::uint32_t count = keys_.count(slot);
    const double epochIndex = std::floor((time - timing_.delay) / kEpochSeconds);
    const auto epoch = static_cast<float>(epochIndex);
    const auto clock = static_cast<float>(time - timing_.delay - epochIndex * kEpochSeconds);
    const gpu::DrivenModel& model = drivenModels_[characters_[slot].model];
    // The newest key at or before the clock (the oldest the ring holds when the clock is before it).
    std::uint32_t k = count - 1;
    const std::uint32_t oldest = keys_.oldest(slot);
    while (k > oldest && driven::drivenKeyTime(keys_.key(slot, k), epoch) > clock) --k;
    const gpu::DrivenKey& a = keys_.key(slot, k);
    const float ta = driven::drivenKeyTime(a, epoch);
    driven::DrivenPose pose;
    if (k + 1 < count) {
        const gpu::DrivenKey& b = keys_.key(slot, k + 1);
        pose = driven::drivenBetween(a, b, ta, driven::drivenKeyTime(b, epoch), clock);
    } else if (clock <= ta) {
        pose = driven::drivenAt(a);
    } else {
        const bool only = k == oldest;
        const gpu::DrivenKey& previous = keys_.key(slot, only ? k : k - 1);
        pose = driven::drivenBeyond(previous, a, only, driven::drivenKeyTime(previous, epoch), ta, clock,
                                    static_cast<float>(timing_.extrapolate), epoch, model);
    }
    MotionState state = drivenMotionState(pose, model);
    // The clips' own sway: the root motion that keeps their planted feet still, less its straight stride
    // (the path the samples give is that straight line), weighted as the clips are (as the motion pass does).
    const std::uint32_t m = characters_[slot].model;
    const float cycle = state.phase - std::floor(state.phase);
    auto sway = [&](std::uint32_t clip) {
        return library_.rootMotion(m, clip, cycle) - cycle * library_.stride(m, clip);
    };
    const glm::vec2 offset = turnToWorld(glm::mix(sway(state.clipFrom), sway(state.clipTo), state.weight), state.heading);
    state.position.x += offset.x;
    state.position.z += offset.y;
    return state;
}

Identity Crowd::identity(std::uint32_t slot) const {
    const Character& c = characters_[slot];
    return {glm::vec4(c.tint, population_.alive(slot) ? c.scale : 0.0f), population_.alive(slot) ? c.props : 0u,
            population_.generation(slot)};
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
        // Back in time: every living character's plan starts over from the layout.
        earlier_.clear();
        added_.clear();
        lastChanged_.clear();
        calendar_.clear();
        for (std::uint32_t s = 0; s < size(); ++s)
            if (population_.alive(s)) startSlot(s);
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
        changes_.markAll();
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
    if (!newEpoch)
        for (const std::uint32_t c : lastChanged_) changes_.mark(c);
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
    if (!population_.alive(character))
        throw gpu::Error("character " + std::to_string(character) + ": its slot is free (removed, or not yet spawned)");
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

MotionState Crowd::flatStateAt(std::uint32_t index, double time) const {
    if (characters_[index].driven == Driven::HostSamples && !keys_.empty() && keys_.count(index) > 0)
        return drivenState(index, time);
    return evaluateMotion(segments_[index], static_cast<float>(time - epoch_), library_, characters_[index].model);
}

MotionState Crowd::stateAt(std::uint32_t index, double time) const { return onGround(flatStateAt(index, time)); }

MotionState Crowd::onGround(MotionState state) const {
    state.position.y += terrain_.height(glm::vec2(state.position.x, state.position.z));
    return state;
}

void Crowd::setTerrain(const Terrain& terrain) {
    terrain_ = terrain;
    ++terrainVersion_;
}

MotionState Crowd::stateKnown(std::uint32_t index, double time) const {
    checkCharacter(index);
    checkKnowable(index);
    if (characters_[index].driven == Driven::HostSamples && !keys_.empty() && keys_.count(index) > 0) {
        // The ring holds its last keys: times before the oldest (drawn late by the delay) are forgotten.
        const double oldest = keySceneTime(keys_.key(index, keys_.oldest(index))) + timing_.delay;
        if (keys_.oldest(index) > 0 && time < oldest)
            throw gpu::Error("character " + std::to_string(index) + ": time " + std::to_string(time) + " s is before " +
                             std::to_string(oldest) + " s, its oldest key kept (the capacity's drivenKeys a character)");
        return onGround(drivenState(index, time));
    }
    if (!(time >= knownFrom_[index]))
        throw gpu::Error("character " + std::to_string(index) + ": time " + std::to_string(time) +
                         " s is before " + std::to_string(knownFrom_[index]) +
                         " s, the earliest its plans still hold (query each frame's window as you advance)");
    const std::uint32_t model = characters_[index].model;
    if (time >= plans_[index].start || std::isinf(knownFrom_[index])) return stateAt(index, time);  // on the ground
    const Segment* segment = &previous_[index];
    if (time < previous_[index].start)
        for (const auto& [character, s] : earlierOf(index))
            if (s.start <= time) segment = &s;
    return onGround(evaluateMotion(recordFrom(*segment, epoch_, library_, model), static_cast<float>(time - epoch_),
                                   library_, model));
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
        checkKnowable(c);
        const std::uint32_t model = characters_[c].model;
        const double since = std::max(from, bornAt_[c]);  // nothing it fired before it was spawned
        if (characters_[c].driven == Driven::HostSamples && !keys_.empty() && keys_.count(c) > 0) {
            const double oldest = keySceneTime(keys_.key(c, keys_.oldest(c))) + timing_.delay;
            if (keys_.oldest(c) > 0 && from < oldest)
                throw gpu::Error("character " + std::to_string(c) + ": events from " + std::to_string(from) +
                                 " s asked, but its oldest key kept is drawn at " + std::to_string(oldest) + " s");
            // One character's events at a time, in time order, into the sink (kept while it has room).
            thread_local std::vector<FiredEvent> fired;
            fired.clear();
            drivenEvents(keys_, c, *models_[model], library_, model, drivenModels_[model], timing_, since, to, fired);
            for (const FiredEvent& event : fired) {
                if (out.kept && out.count < out.room) out.kept->push_back(event);
                ++out.count;
            }
            continue;
        }
        forEachKnownSegment(c, [&](const Segment& segment, double begin, double end) {
            segmentEvents(segment, *models_[model], library_, model, c, begin, end, since, to, out);
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
            if (!population_.alive(i)) continue;  // a free slot: no bones (its scale 0 culls it)
            // The motion is evaluated once for both the bones and the record.
            const MotionState state = stateAt(i, time);
            animateState(i, state, out.subspan(boneOffsets[i]));
            if (!records.empty()) writePose(state, records[i]);
        }
    });
}

const Crowd::Bounds& Crowd::bounds() const {
    if (world_.lo.x <= world_.hi.x) return world_;
    const std::uint64_t version = population_.version() + reachVersion_;
    if (measuredVersion_ == version) return measured_;
    Bounds b = drivenReach_;
    for (std::uint32_t s = 0; s < size(); ++s) {
        if (!population_.alive(s)) continue;
        const Character& c = characters_[s];
        b.lo = glm::min(b.lo, c.position), b.hi = glm::max(b.hi, c.position);
        b.tallest = std::max(b.tallest, models_[c.model]->height() * c.scale);
    }
    if (population_.live() == 0) b.tallest = models_[0]->height();
    if (b.lo.x <= b.hi.x) {
        glm::vec3 hi = b.hi;
        // A formation marches out along +z and back: the middle of its beat.
        if (behaviour_.kind == Behaviour::March) hi.z += behaviour_.marchLength;
        b.center = 0.5f * (b.lo + hi);
        // The farthest living character (or driven sample's box corner) from the centre.
        for (std::uint32_t s = 0; s < size(); ++s)
            if (population_.alive(s)) b.farthest = std::max(b.farthest, glm::length(characters_[s].position - b.center));
        if (drivenReach_.lo.x <= drivenReach_.hi.x)
            b.farthest = std::max(b.farthest, glm::length(glm::max(glm::abs(drivenReach_.lo - b.center),
                                                                   glm::abs(drivenReach_.hi - b.center))));
    }
    measured_ = b;
    measuredVersion_ = version;
    return measured_;
}

void Crowd::setWorldBounds(const glm::vec3& lo, const glm::vec3& hi) {
    if (!(std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) && std::isfinite(hi.x) &&
          std::isfinite(hi.y) && std::isfinite(hi.z)))
        throw gpu::Error("world bounds must be finite");
    world_.lo = lo;
    world_.hi = hi;
    world_.center = 0.5f * (lo + hi);
    world_.farthest = glm::length(0.5f * (hi - lo));
    float tallest = 0.0f;
    for (const model::SkinnedModel* m : models_) tallest = std::max(tallest, m->height());
    world_.tallest = tallest;
}

glm::vec3 Crowd::center() const { return bounds().center; }

float Crowd::radius() const {
    const Bounds& b = bounds();
    float widest = 0.0f;
    for (const model::SkinnedModel* m : models_) {
        const glm::vec3 extent = m->boundsMax - m->boundsMin;
        widest = std::max(widest, std::max(extent.x, extent.z));
    }
    // Characters that move stay within their behaviour's reach of where they started.
    float reach = 0.0f;
    if (&b != &world_ && behaviour_.kind == Behaviour::Mill) reach = behaviour_.millRadius + 1.0f;
    if (&b != &world_ && behaviour_.kind == Behaviour::March) reach = 2.0f;  // the centre already spans its beat
    return b.farthest + 0.5f * widest + reach;
}

float Crowd::tallestHeight() const { return bounds().tallest; }

}  // namespace crowd
