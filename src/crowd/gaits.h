#pragma once
// Which of a model's clips a behaviour uses to stand, walk and run. By name first ("idle" or
// "survey"; "walk"; "run" or "gallop", any case), then by measured root motion: the slowest clip
// that travels walks, the fastest runs, one that stays in place stands.
#include <cstdint>

#include "anim/clip_library.h"
#include "model/skinned_model.h"

namespace crowd {

struct Gaits {
    static constexpr std::int32_t kNone = -1;
    std::int32_t stand = kNone;
    std::int32_t walk = kNone;
    std::int32_t run = kNone;
    bool canTravel() const { return walk != kNone; }
};

Gaits findGaits(const model::SkinnedModel& model, const anim::ClipLibrary& library, std::uint32_t libraryModel);

}  // namespace crowd
