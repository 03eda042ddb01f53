// crowdgpu::Crowd over crowd::Crowd: conversions of the public value types, and errors.
#include "crowdgpu/crowd.hpp"

#include <cmath>
#include <cstring>

#include "api/api_data.h"
#include "api/crowd_arguments.h"
#include "crowd/host_memory.h"
#include "crowd/worker_pool.h"

static_assert(crowdgpu::kMaxCrowdModels == MAX_MODELS, "the public limit is the shaders' table size");

namespace crowdgpu {
namespace detail {

std::vector<const model::SkinnedModel*> internalModels(const std::vector<Model>& models) {
    std::vector<const model::SkinnedModel*> result;
    for (const Model& m : models) result.push_back(&m.data()->model);
    return result;
}

}  // namespace detail
namespace {

crowd::Character toInternal(const Character& c) {
    crowd::Character result;
    result.model = c.model;
    result.clip = c.clip;
    result.timeOffset = c.phase;
    result.speed = c.speed;
    result.position = glm::vec3(c.position[0], c.position[1], c.position[2]);
    result.heading = c.heading;
    result.scale = c.scale;
    result.tint = glm::vec3(c.tint[0], c.tint[1], c.tint[2]);
    result.props = c.props;
    result.driven = c.motion == MotionSource::HostSamples     ? crowd::Driven::HostSamples
                    : c.motion == MotionSource::DeviceSamples ? crowd::Driven::DeviceSamples
                                                              : crowd::Driven::No;
    return result;
}

// Frees a thread's scratch list when a call grew it past what a frame needs (65,536 events, 1.5 MiB:
// a frame's window of a million walking characters), so no thread keeps a high-water mark for life.
struct ScratchRelease {
    static constexpr std::size_t kKept = 65536;
    std::vector<crowd::FiredEvent>& scratch;
    ~ScratchRelease() {
        if (scratch.capacity() > kKept) std::vector<crowd::FiredEvent>().swap(scratch);
    }
};

crowd::BehaviourSettings behaviourOf(Behaviour behaviour, std::uint32_t seed) {
    detail::checkBehaviour("Crowd", behaviour);
    crowd::BehaviourSettings settings;
    settings.kind = behaviour == Behaviour::March ? crowd::Behaviour::March
                    : behaviour == Behaviour::Mill ? crowd::Behaviour::Mill
                                                   : crowd::Behaviour::InPlace;
    settings.seed = seed;
    return settings;
}

std::unique_ptr<detail::CrowdData> makeData(std::vector<Model> models, std::vector<crowd::Character> characters,
                                            Behaviour behaviour, std::uint32_t seed, const CrowdCapacity& capacity) {
    if (models.empty()) throw Error(ErrorCode::InvalidArgument, "a crowd needs at least one model");
    if (capacity.perModel.size() > models.size())
        throw Error(ErrorCode::InvalidArgument, "a capacity for " + std::to_string(capacity.perModel.size()) +
                                                    " models, but the crowd has " + std::to_string(models.size()));
    return detail::translated([&] {
        const std::vector<const model::SkinnedModel*> pointers = detail::internalModels(models);
        return std::unique_ptr<detail::CrowdData>(
            new detail::CrowdData{std::move(models),
                                  crowd::Crowd(pointers, std::move(characters), behaviourOf(behaviour, seed),
                                               crowd::Capacity{capacity.perModel, capacity.drivenKeys}),
                                  nullptr});
    });
}

crowd::Handle toInternal(CharacterHandle h) { return {h.slot, h.generation}; }

}  // namespace

Crowd::Crowd(std::unique_ptr<detail::CrowdData> data) : data_(std::move(data)) {}

Crowd::Crowd(std::vector<Model> models, std::vector<Character> characters, Behaviour behaviour, std::uint32_t seed,
             const CrowdCapacity& capacity) {
    std::vector<crowd::Character> internal;
    internal.reserve(characters.size());
    for (std::size_t i = 0; i < characters.size(); ++i)
        if (!detail::characterInRange(characters[i]))
            detail::checkCharacter("Crowd", "character " + std::to_string(i), characters[i]);
    for (const Character& c : characters) internal.push_back(toInternal(c));
    data_ = makeData(std::move(models), std::move(internal), behaviour, seed, capacity);
}

Crowd Crowd::grid(std::vector<Model> models, const GridLayout& layout, Behaviour behaviour, const CrowdCapacity& capacity) {
    detail::checkGridLayout(layout);
    detail::checkBehaviour("Crowd::grid", behaviour);
    crowd::LayoutOptions options;
    options.count = layout.count;
    options.seed = layout.seed;
    options.weights = layout.weights;
    options.clips.assign(layout.clips.begin(), layout.clips.end());
    options.randomClips = layout.randomClips;
    options.formation = layout.formation;
    options.depthRatio = layout.depthRatio;
    options.scaleVariation = layout.scaleVariation;
    options.tintVariation = layout.tintVariation;
    options.props = layout.props;
    options.scales = layout.scales;
    std::vector<crowd::Character> characters = detail::translated(
        [&] { return crowd::gridLayout(detail::internalModels(models), options); });
    Character mover;
    mover.motion = layout.motion;
    for (crowd::Character& c : characters) c.driven = toInternal(mover).driven;
    return Crowd(makeData(std::move(models), std::move(characters), behaviour, layout.seed, capacity));
}

Crowd::~Crowd() = default;
Crowd::Crowd(Crowd&&) noexcept = default;
Crowd& Crowd::operator=(Crowd&&) noexcept = default;

std::uint32_t Crowd::size() const { return data_->crowd().size(); }
const std::vector<Model>& Crowd::models() const { return data_->models; }

std::uint32_t Crowd::liveCount() const { return data_->crowd().population().live(); }

CharacterHandle Crowd::spawn(const Character& character) {
    detail::checkCharacter("spawn", "the character", character);
    return detail::translated([&] {
        const crowd::Handle h = data_->crowd().spawn(toInternal(character));
        return CharacterHandle{h.slot, h.generation};
    });
}

void Crowd::spawn(const Character* characters, std::size_t count, CharacterHandle* handles) {
    if (count == 0) return;
    if (characters == nullptr || handles == nullptr)
        throw Error(ErrorCode::InvalidArgument, "spawn: a batch of " + std::to_string(count) + " needs its characters "
                                                "and room for their handles (a null pointer)");
    // Scratch kept by the thread: a game's every-frame batch allocates nothing once warm.
    thread_local std::vector<crowd::Character> internal;
    thread_local std::vector<crowd::Handle> made;
    internal.resize(count);
    made.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (!detail::characterInRange(characters[i]))
            detail::checkCharacter("spawn", "character " + std::to_string(i) + " of the batch", characters[i]);
        internal[i] = toInternal(characters[i]);
    }
    detail::translated([&] { data_->crowd().spawn(internal.data(), count, made.data()); });
    for (std::size_t i = 0; i < count; ++i) handles[i] = {made[i].slot, made[i].generation};
}

void Crowd::remove(CharacterHandle character) {
    detail::translated([&] { data_->crowd().remove(toInternal(character)); });
}

void Crowd::remove(const CharacterHandle* characters, std::size_t count) {
    if (count == 0) return;
    if (characters == nullptr)
        throw Error(ErrorCode::InvalidArgument, "remove: a batch of " + std::to_string(count) + " handles is null");
    thread_local std::vector<crowd::Handle> internal;
    internal.resize(count);
    for (std::size_t i = 0; i < count; ++i) internal[i] = toInternal(characters[i]);
    detail::translated([&] { data_->crowd().remove(internal.data(), count); });
}

bool Crowd::alive(CharacterHandle character) const { return data_->crowd().population().valid(toInternal(character)); }

CharacterHandle Crowd::handle(std::uint32_t slot) const {
    const crowd::Population& population = data_->crowd().population();
    if (!population.alive(slot))
        throw Error(ErrorCode::InvalidArgument, slot < population.slots()
                                                    ? "slot " + std::to_string(slot) + " is free (no living character)"
                                                    : "no slot " + std::to_string(slot) + " in a crowd of " +
                                                          std::to_string(population.slots()));
    const crowd::Handle h = population.handle(slot);
    return {h.slot, h.generation};
}

void Crowd::moveTo(std::uint32_t character, float x, float z, double at, std::int32_t gait, float rate) {
    detail::checkMoveTo(x, z, at, rate);
    detail::translated([&] { data_->crowd().moveTo(character, glm::vec2(x, z), at, gait, rate); });
}

void Crowd::play(std::uint32_t character, std::int32_t clip, double at, float fade, float rate) {
    detail::checkPlay(at, fade, rate);
    detail::translated([&] { data_->crowd().play(character, clip, at, fade, rate); });
}

void Crowd::advanceTo(double time) {
    detail::checkTime("advanceTo", "time", time);
    detail::translated([&] { data_->crowd().advanceTo(time); });
}

CharacterState Crowd::stateAt(std::uint32_t character, double time) const {
    detail::checkTime("stateAt", "time", time);
    if (character >= size())
        throw Error(ErrorCode::InvalidArgument, "no character " + std::to_string(character) + " in a crowd of " +
                                                    std::to_string(size()));
    if (!data_->crowd().alive(character))
        throw Error(ErrorCode::InvalidArgument, "character " + std::to_string(character) +
                                                    ": its slot is free (removed, or not yet spawned)");
    if (data_->crowd().drivenBy(character) == crowd::Driven::DeviceSamples)
        throw Error(ErrorCode::Unsupported, "character " + std::to_string(character) +
                                                ": driven by a device buffer, its motion is the GPU's alone");
    const crowd::MotionState s = data_->crowd().stateAt(character, time);
    return {{s.position.x, s.position.y, s.position.z}, s.heading, s.clipFrom, s.clipTo, s.weight, s.phase};
}

DriveResult Crowd::drive(const SampleBatch& samples) {
    return detail::translated([&] {
        const bool arrays = samples.characters && samples.times && samples.x && samples.z;
        if (samples.count > 0 && !arrays)
            throw Error(ErrorCode::InvalidArgument, "drive: the characters, times, x or z array is null");
        static_assert(sizeof(CharacterHandle) == sizeof(crowd::Handle));
        const std::size_t n = samples.count;
        crowd::SampleBatch batch{{reinterpret_cast<const crowd::Handle*>(samples.characters), n},
                                 {samples.times, n},
                                 {samples.x, n},
                                 {samples.z, n},
                                 samples.headings ? std::span<const float>(samples.headings, n) : std::span<const float>()};
        const crowd::DriveResult r = data_->crowd().drive(batch);
        return DriveResult{r.applied, r.late};
    });
}

void Crowd::setDrivenTiming(const DrivenTiming& timing) {
    detail::translated([&] { data_->crowd().setDrivenTiming({timing.delay, timing.extrapolate}); });
}

DrivenTiming Crowd::drivenTiming() const {
    const crowd::DrivenTiming& t = data_->crowd().drivenTiming();
    return {t.delay, t.extrapolate};
}

void Crowd::setGaitSettings(std::uint32_t model, const GaitSettings& s) {
    detail::translated([&] {
        data_->crowd().setGaitBands(model, {s.walkFrom, s.runFrom, s.hysteresis, s.fade, s.turnRate, s.turnSpeed});
    });
}

GaitSettings Crowd::gaitSettings(std::uint32_t model) const {
    if (model >= models().size())
        throw Error(ErrorCode::InvalidArgument, "gait settings: no model " + std::to_string(model) + " (the crowd has " +
                                                    std::to_string(models().size()) + ")");
    const crowd::GaitBands& b = data_->crowd().gaitBands(model);
    return {b.walkFrom, b.runFrom, b.hysteresis, b.fade, b.turnRate, b.turnSpeed};
}

std::uint64_t Crowd::paletteJoints() const {
    std::uint64_t joints = 0;
    for (const crowd::Character& c : data_->crowd().characters()) joints += data_->crowd().library().jointCount(c.model);
    return joints;
}

void Crowd::computePalettes(double time, std::vector<float>& rows, bool allCores) const {
    detail::checkTime("computePalettes", "time", time);
    detail::translated([&] {
        const crowd::Crowd& crowd = data_->crowd();
        std::vector<std::uint32_t> offsets(crowd.size());
        std::uint64_t joints = 0;
        for (std::uint32_t c = 0; c < crowd.size(); ++c)
            offsets[c] = static_cast<std::uint32_t>(joints), joints += crowd.library().jointCount(crowd.characters()[c].model);
        static_assert(sizeof(gpu::BoneRows) == 12 * sizeof(float));
        rows.resize(joints * 12);
        const std::span<gpu::BoneRows> bones(reinterpret_cast<gpu::BoneRows*>(rows.data()), joints);
        static crowd::WorkerPool callingThread(1);  // no workers: the caller does every chunk
        crowd.animate(time, bones, offsets, {}, allCores ? &crowd::WorkerPool::shared() : &callingThread);
        for (std::uint32_t c = 0; c < crowd.size(); ++c)  // a free slot's rows: zeros, not last call's
            if (!crowd.alive(c))
                std::fill_n(rows.begin() + 12 * std::ptrdiff_t{offsets[c]}, 12 * crowd.library().jointCount(crowd.characters()[c].model), 0.0f);
    });
}

void Crowd::jointWorld(std::uint32_t character, std::uint32_t joint, double time, float out[12]) const {
    detail::checkTime("jointWorld", "time", time);
    detail::translated([&] {
        const gpu::BoneRows rows = data_->crowd().jointWorld(character, joint, time);
        static_assert(sizeof(gpu::BoneRows) == 12 * sizeof(float));
        std::memcpy(out, &rows, sizeof rows);
    });
}

void Crowd::events(const std::uint32_t* characters, std::size_t count, double from, double to,
                   std::vector<Event>& out) const {
    events(characters, count, from, to, out, SIZE_MAX);
}

std::uint64_t Crowd::events(const std::uint32_t* characters, std::size_t count, double from, double to,
                            std::vector<Event>& out, std::size_t capacity) const {
    detail::checkEventWindow(characters, count, from, to);
    out.clear();
    return detail::translated([&] {
        // This thread's scratch: a host asking every frame allocates nothing once warm, and a rare
        // large list does not keep its memory after the call, thrown or not.
        thread_local std::vector<crowd::FiredEvent> fired;
        const ScratchRelease release{fired};
        fired.clear();
        crowd::EventSink sink{capacity > 0 ? &fired : nullptr, capacity};
        data_->crowd().events({characters, count}, from, to, sink);
        if (sink.count <= capacity) {
            out.reserve(fired.size());
            for (const crowd::FiredEvent& e : fired) out.push_back({e.character, e.clip, e.event, e.time});
        }
        return sink.count;
    });
}

std::uint64_t hostBytesNeeded(const std::vector<Model>& models, std::uint64_t characters, bool cpuPalettes) {
    return crowd::estimateHostBytes(detail::internalModels(models), characters, cpuPalettes);
}

void setWorkerThreads(unsigned threads) {
    if (threads > 1024)
        throw Error(ErrorCode::InvalidArgument, "worker threads: " + std::to_string(threads) + " is over 1024");
    crowd::WorkerPool::setSharedThreads(threads);
}

unsigned workerThreads() { return crowd::WorkerPool::sharedThreads(); }

const char* behaviourName(Behaviour behaviour) {
    return crowd::behaviourName(behaviour == Behaviour::March ? crowd::Behaviour::March
                                : behaviour == Behaviour::Mill ? crowd::Behaviour::Mill
                                                               : crowd::Behaviour::InPlace);
}

Character Crowd::character(std::uint32_t character) const {
    handle(character);  // checks the slot: it holds a living character
    const crowd::Character& c = data_->crowd().characters()[character];
    Character result;
    result.model = c.model;
    result.clip = c.clip;
    result.phase = c.timeOffset;
    result.speed = c.speed;
    result.position[0] = c.position.x, result.position[1] = c.position.y, result.position[2] = c.position.z;
    result.heading = c.heading;
    result.scale = c.scale;
    result.tint[0] = c.tint.x, result.tint[1] = c.tint.y, result.tint[2] = c.tint.z;
    result.props = c.props;  // as resolved: the props it carries
    result.motion = c.driven == crowd::Driven::HostSamples     ? MotionSource::HostSamples
                    : c.driven == crowd::Driven::DeviceSamples ? MotionSource::DeviceSamples
                                                               : MotionSource::Behaviour;
    return result;
}

void Crowd::setTerrain(const Heightfield& ground) {
    detail::translated([&] {
        if (ground.columns == 0 && ground.rows == 0) return data_->crowd().setTerrain(crowd::Terrain());
        if (!ground.heights) throw Error(ErrorCode::InvalidArgument, "terrain: no heights");
        crowd::Heightfield field;
        field.columns = ground.columns, field.rows = ground.rows;
        const std::uint64_t samples = std::uint64_t{ground.columns} * ground.rows;
        if (samples > (std::uint64_t{1} << 25))
            throw Error(ErrorCode::InvalidArgument, "terrain: " + std::to_string(samples) + " samples, at most 2^25");
        field.heights.assign(ground.heights, ground.heights + samples);
        field.origin = glm::vec2(ground.origin[0], ground.origin[1]);
        field.size = glm::vec2(ground.size[0], ground.size[1]);
        data_->crowd().setTerrain(crowd::Terrain(std::move(field)));
    });
}

float Crowd::groundHeight(float x, float z) const { return data_->crowd().terrain().height(glm::vec2(x, z)); }

void Crowd::setWorldBounds(const float lo[3], const float hi[3]) {
    detail::translated([&] {
        if (!lo || !hi) throw Error(ErrorCode::InvalidArgument, "world bounds: lo or hi is null");
        if (!(lo[0] < hi[0] && lo[1] <= hi[1] && lo[2] < hi[2]))
            throw Error(ErrorCode::InvalidArgument, "world bounds: lo must lie below hi on each axis");
        data_->crowd().setWorldBounds(glm::vec3(lo[0], lo[1], lo[2]), glm::vec3(hi[0], hi[1], hi[2]));
    });
}

void Crowd::bounds(float center[3], float& radius, float& tallest) const {
    const glm::vec3 c = data_->crowd().center();
    center[0] = c.x, center[1] = c.y, center[2] = c.z;
    radius = data_->crowd().radius();
    tallest = data_->crowd().tallestHeight();
}

}  // namespace crowdgpu
