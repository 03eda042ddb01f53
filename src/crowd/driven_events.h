#pragma once
// The animation events a driven character fires (crowd/events.h's rules on keys, shaders/driven_keys.h):
// between two keys its phase and gait are linear in time, so each event's moment is solved, not
// stepped: where the phase meets its point (a pair of a crossfade's two clips, where it meets their
// points blended by the weight; any other event while its clip weighs more).
#include <cstdint>
#include <vector>

#include "anim/clip_library.h"
#include "crowd/driven.h"
#include "crowd/events.h"
#include "model/skinned_model.h"

namespace crowd {

// Appends to `out` the events slot `slot` (driven from the host's memory, with keys) fires at scene
// times t, from < t <= to, in time order; `timing`'s delay shifts the keys onto the scene clock and its
// extrapolation carries the character past its newest key. `from` must not lie before the oldest key
// the ring holds (plus the delay): the caller checks.
void drivenEvents(const DrivenKeys& keys, std::uint32_t slot, const model::SkinnedModel& model,
                  const anim::ClipLibrary& library, std::uint32_t modelIndex, const gpu::DrivenModel& driven,
                  const DrivenTiming& timing, double from, double to, std::vector<FiredEvent>& out);

}  // namespace crowd
