#pragma once
// PeTrack tracks heads, and a head sways 2-3 cm to the side of the step's foot at every step: a
// character placed on the raw track wobbles at the stride's rhythm, which its walk clip already
// shows once. Smoothing each track over a time window takes the sway out and keeps the path.
#include <cstddef>
#include <cstdint>

#include "replay/trajectory.h"

namespace replay {

// The corridor's heads sway at 0.85 Hz (a stride). 0.6 s takes a quarter of the sway out (lateral RMS
// about a smooth path 34 -> 26 mm) and moves no sample more than 8.6 cm; 1.0 s halves it but reaches
// 10 cm at the corridor's sharpest turns (docs/host-driven.md, "Smoothing", has the measurements).
inline constexpr double kDefaultSmoothingWindow = 0.6;
// And how far a sample may move, at most: 2.5 cm keeps the sway out and the corners where they were, so a
// character's root (its clips' own sway added, 6.9 cm at the most for the soldier's walk) stays within
// 10 cm of the recording (tests/test_replay_motion.cpp measures it on the corridor).
inline constexpr double kDefaultSmoothingShift = 0.025;

// How far smoothing moved the samples, metres, and where it moved one most.
struct SmoothingReport {
    double window = 0.0;
    std::size_t samples = 0;
    double maxDeviation = 0.0;
    double meanDeviation = 0.0;
    std::int64_t maxId = 0;  // the file's id of the person moved most, and when
    double maxTime = 0.0;
};

// Replaces each track's positions by a centred Gaussian average over `window` seconds (the standard
// deviation of a `window`-long moving average, window / sqrt(12), cut at 3 of them; in time, so
// uneven sampling is weighted by time, not by count). Near a track's ends the kernel narrows
// symmetrically to what both sides have, so the first and last positions stay exactly as recorded and
// the path is not pulled inwards at its ends. Times are unchanged; the recording's extent is updated.
// window 0 leaves the recording as it is. A sample moved further than `maxShift` metres (where the
// average cuts a sharp turn) is moved back towards the recording to that distance: the sway the average
// takes out is a few centimetres, the corners it would cut are not. Costs O(samples x samples per window).
SmoothingReport smoothPaths(Recording& recording, double window, double maxShift = 1e30);

}  // namespace replay
