#pragma once
// A planned motion segment on the scene clock, and the record of it the GPU evaluates.
//
// A plan keeps its start as a double and its record's own times (crossfade, turn) relative to that
// start, so a plan made at 1e7 s is as exact as one made at 0 s. What reaches the GPU (and the CPU
// reference, which repeats the GPU's float arithmetic) is the record relative to an epoch near the
// frame's time (crowd/epoch.h): a segment whose turn and crossfade ended before the epoch is restated
// as where it stands at the epoch, its whole cycles taken out in double, so no float ever holds a large
// time, phase or number of strides.
#include <cstdint>

#include "anim/clip_library.h"
#include "crowd/motion.h"
#include "gpu_types.h"

namespace crowd {

struct Segment {
    double start = 0.0;          // scene seconds
    gpu::MotionRecord motion{};  // timing.x = 0: its times count from `start`
    // Cycles per second of the clip faded to, as exactly as it was chosen (motion.phase.z rounds it to
    // a float: an in-place loop an hour or a year long would drift from its clip's period by whole
    // frames). 0: motion.phase.z is exact.
    double rate = 0.0;
};

// The record of `segment` relative to `epoch` (timing.x = start - epoch, in float), what the motion
// pass evaluates at (float)(time - epoch).
gpu::MotionRecord recordFrom(const Segment& segment, double epoch, const anim::ClipLibrary& library, std::uint32_t model);

// Where a character following `segment` is and what it plays at `time`, exact however long after the
// segment's start (before it: its start).
MotionState stateOf(const Segment& segment, double time, const anim::ClipLibrary& library, std::uint32_t model);

// The phase at `time` in cycles from the segment's own (its record's phase.x), whole cycles kept.
double unwrappedPhase(const Segment& segment, double time);

// Seals the segment's curved part (crowd::sealSegment).
void seal(Segment& segment, const anim::ClipLibrary& library, std::uint32_t model);

}  // namespace crowd
