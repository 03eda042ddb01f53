#pragma once
// Animation events of the crowd: when a character's phase passes a clip event's point in the cycle
// (anim::ClipEvent), the event fires. The phase is closed form (crowd/motion.h), so each firing time is
// solved from the segment, not found by stepping frames: a window (from, to] gets the same events in one
// call as in any number of calls that split it.
//
// Crossfades: both clips sit at the same point of their cycles, so both clips' events could fire.
// Events that pair (crowd/event_pairs.h: a walk's and a run's footstep of one foot) fire once, where
// the phase meets their points blended by the weight, so the fade neither skips nor repeats a step;
// any other event fires from its clip while that clip weighs more (the clip faded to from half way
// on). docs/events.md#firing.
#include <cstdint>
#include <vector>

#include "anim/clip_library.h"
#include "crowd/segment.h"
#include "model/skinned_model.h"

namespace crowd {

struct FiredEvent {
    std::uint32_t character = 0;
    std::uint32_t clip = 0;   // the model's clip
    std::uint32_t event = 0;  // index into that clip's events
    double time = 0.0;        // scene seconds
};

// Where fired events go: every one is counted, and the first `room` are appended to `kept` (none without
// it), so a count costs no storage and a list no more than the caller allows. When more fire than
// there is room for, which of them were kept is unspecified: callers refuse such a list.
struct EventSink {
    std::vector<FiredEvent>* kept = nullptr;
    std::uint64_t room = UINT64_MAX;
    std::uint64_t count = 0;
};

// The most cycles of one clip a window may cover for one character's segment (about 10 ms of work per
// event of the clip): beyond it segmentEvents throws gpu::Error rather than run on (a clip of a
// millisecond played fast over a long window).
inline constexpr double kMostCyclesInWindow = 1e6;

// Adds to `out` the events `character` fires while following `segment` (of `model`, the library's
// model `modelIndex`) at times t with from < t <= to and begin <= t < end (the part of the scene clock
// the segment covers). Kept in time order.
void segmentEvents(const Segment& segment, const model::SkinnedModel& model, const anim::ClipLibrary& library,
                   std::uint32_t modelIndex, std::uint32_t character, double begin, double end, double from,
                   double to, EventSink& out);

}  // namespace crowd
