#include "crowd/driven.h"

#include <algorithm>
#include <cmath>

#include "crowd/epoch.h"

namespace crowd {
namespace {

// Metres a cycle of the clip carries its character (0: it stays in place), and its cycles a second.
float strideOf(const anim::ClipLibrary& library, std::uint32_t model, std::int32_t clip) {
    return clip == Gaits::kNone ? 0.0f : glm::length(library.stride(model, static_cast<std::uint32_t>(clip)));
}
float cyclesOf(const anim::ClipLibrary& library, std::uint32_t model, std::int32_t clip) {
    if (clip == Gaits::kNone) return 0.0f;
    const float duration = library.duration(model, static_cast<std::uint32_t>(clip));
    return duration > 0.0f ? 1.0f / duration : 0.0f;
}

}  // namespace

GaitBands defaultGaitBands(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits) {
    const float walk = strideOf(library, model, gaits.walk) * cyclesOf(library, model, gaits.walk);
    const float run = strideOf(library, model, gaits.run) * cyclesOf(library, model, gaits.run);
    GaitBands bands;
    // A model whose walk does not travel: human walking speeds.
    const float walkSpeed = walk > 0.0f ? walk : 1.4f;
    bands.walkFrom = 0.1f * walkSpeed;
    bands.runFrom = run > walkSpeed ? 0.5f * (walkSpeed + run) : 3.0f * walkSpeed;
    return bands;
}

gpu::DrivenModel drivenModel(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                             const GaitBands& bands) {
    // A gait the model lacks plays its neighbour's clip: no stand, the walk (at rate 0: still); no run,
    // the walk (faster); no walk, the stand (or its first clip).
    const std::int32_t first = library.clipCount(model) > 0 ? 0 : Gaits::kNone;
    const std::int32_t walk = gaits.walk != Gaits::kNone ? gaits.walk : (gaits.stand != Gaits::kNone ? gaits.stand : first);
    const std::int32_t stand = gaits.stand != Gaits::kNone ? gaits.stand : walk;
    const std::int32_t run = gaits.run != Gaits::kNone ? gaits.run : walk;
    auto index = [](std::int32_t clip) { return static_cast<std::uint32_t>(std::max(clip, 0)); };
    gpu::DrivenModel m{};
    m.clips = glm::uvec4(index(stand), index(walk), index(run), 0u);
    m.cycles = glm::vec4(gaits.stand != Gaits::kNone ? cyclesOf(library, model, stand) : 0.0f,
                         strideOf(library, model, walk), strideOf(library, model, run), cyclesOf(library, model, walk));
    m.bands = glm::vec4(bands.walkFrom, bands.runFrom, bands.hysteresis, bands.fade);
    m.turning = glm::vec4(bands.turnRate, bands.turnSpeed, 0.0f, 0.0f);
    return m;
}

DrivenKeys::DrivenKeys(std::uint32_t slots, std::uint32_t perSlot)
    : perSlot_(perSlot), keys_(std::size_t{slots} * perSlot), counts_(slots, 0u) {}

double keySceneTime(const gpu::DrivenKey& key) {
    return static_cast<double>(key.motion.w) * kEpochSeconds + static_cast<double>(key.place.x);
}

}  // namespace crowd
