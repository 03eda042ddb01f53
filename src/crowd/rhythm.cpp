#include "crowd/rhythm.h"

#include "crowd/behaviours.h"
#include "crowd/march.h"
#include "crowd/mill.h"

namespace crowd {

Rhythm measureRhythm(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                     const BehaviourSettings& settings) {
    Rhythm rhythm;
    if (!gaits.canTravel()) return rhythm;
    if (settings.kind == Behaviour::Mill) rhythm.millEpisode = millEpisodeLength(library, model, gaits, settings);
    if (settings.kind == Behaviour::March) measureMarch(library, model, gaits, settings, rhythm);
    return rhythm;
}

}  // namespace crowd
