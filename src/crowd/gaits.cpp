#include "crowd/gaits.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace crowd {
namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::int32_t clipNamed(const model::SkinnedModel& model, std::initializer_list<const char*> names) {
    for (const char* name : names)
        for (std::size_t c = 0; c < model.clips.size(); ++c)
            if (lower(model.clips[c].name).find(name) != std::string::npos) return static_cast<std::int32_t>(c);
    return Gaits::kNone;
}

float groundSpeed(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip) {
    const float duration = library.duration(model, clip);
    return duration > 0.0f ? glm::length(library.stride(model, clip)) / duration : 0.0f;
}

}  // namespace

Gaits findGaits(const model::SkinnedModel& model, const anim::ClipLibrary& library, std::uint32_t libraryModel) {
    Gaits gaits;
    gaits.stand = clipNamed(model, {"idle", "survey"});
    gaits.walk = clipNamed(model, {"walk"});
    gaits.run = clipNamed(model, {"run", "gallop"});
    // Unnamed clips by what they do: travelling ones by speed, a still one for standing.
    std::int32_t slowest = Gaits::kNone, fastest = Gaits::kNone;
    for (std::uint32_t c = 0; c < model.clips.size(); ++c) {
        const float speed = groundSpeed(library, libraryModel, c);
        const auto clip = static_cast<std::int32_t>(c);
        if (speed == 0.0f) {
            if (gaits.stand == Gaits::kNone) gaits.stand = clip;
            continue;
        }
        if (slowest == Gaits::kNone || speed < groundSpeed(library, libraryModel, static_cast<std::uint32_t>(slowest))) slowest = clip;
        if (fastest == Gaits::kNone || speed > groundSpeed(library, libraryModel, static_cast<std::uint32_t>(fastest))) fastest = clip;
    }
    // A named gait that measured no travel cannot carry anyone.
    auto travels = [&](std::int32_t c) { return c != Gaits::kNone && groundSpeed(library, libraryModel, static_cast<std::uint32_t>(c)) > 0.0f; };
    if (!travels(gaits.walk)) gaits.walk = slowest;
    if (!travels(gaits.run)) gaits.run = fastest != gaits.walk ? fastest : Gaits::kNone;
    if (gaits.run == gaits.walk) gaits.run = Gaits::kNone;
    return gaits;
}

}  // namespace crowd
