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
                                            Behaviour behaviour, std::uint32_t seed) {
    if (models.empty()) throw Error(ErrorCode::InvalidArgument, "a crowd needs at least one model");
    return detail::translated([&] {
        const std::vector<const model::SkinnedModel*> pointers = detail::internalModels(models);
        return std::unique_ptr<detail::CrowdData>(new detail::CrowdData{
            std::move(models), crowd::Crowd(pointers, std::move(characters), behaviourOf(behaviour, seed)), nullptr});
    });
}

}  // namespace

Crowd::Crowd(std::unique_ptr<detail::CrowdData> data) : data_(std::move(data)) {}

Crowd::Crowd(std::vector<Model> models, std::vector<Character> characters, Behaviour behaviour, std::uint32_t seed) {
    std::vector<crowd::Character> internal;
    internal.reserve(characters.size());
    for (std::size_t i = 0; i < characters.size(); ++i)
        detail::checkCharacter("Crowd", "character " + std::to_string(i), characters[i]);
    for (const Character& c : characters) internal.push_back(toInternal(c));
    data_ = makeData(std::move(models), std::move(internal), behaviour, seed);
}

Crowd Crowd::grid(std::vector<Model> models, const GridLayout& layout, Behaviour behaviour) {
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
    return Crowd(makeData(std::move(models), std::move(characters), behaviour, layout.seed));
}

Crowd::~Crowd() = default;
Crowd::Crowd(Crowd&&) noexcept = default;
Crowd& Crowd::operator=(Crowd&&) noexcept = default;

std::uint32_t Crowd::size() const { return data_->crowd().size(); }
const std::vector<Model>& Crowd::models() const { return data_->models; }

std::uint32_t Crowd::spawn(const Character& character) {
    detail::checkCharacter("spawn", "the character", character);
    return detail::translated([&] { return data_->crowd().spawn(toInternal(character)); });
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
    const crowd::MotionState s = data_->crowd().stateAt(character, time);
    return {{s.position.x, s.position.y, s.position.z}, s.heading, s.clipFrom, s.clipTo, s.weight, s.phase};
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
    stateAt(character, 0.0f);  // checks the index
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
    return result;
}

void Crowd::bounds(float center[3], float& radius, float& tallest) const {
    const glm::vec3 c = data_->crowd().center();
    center[0] = c.x, center[1] = c.y, center[2] = c.z;
    radius = data_->crowd().radius();
    tallest = data_->crowd().tallestHeight();
}

}  // namespace crowdgpu
