#pragma once
// A recording of a few hundred people made into a crowd of any size: N copies side by side in a
// near-square grid, each shifted in time so that the copies do not walk in step. A copy is not a
// copy of the samples (1,000,000 people from the 480-person corridor would be 250 million samples,
// 6 GB): it is a placement per track, an offset in space and time that the feed applies as it reads.
#include <cstdint>
#include <vector>

#include "replay/trajectory.h"

namespace replay {

// One track of a replay: a track of the recording, moved. Its index in the placement list is its
// unique id in the replay; `track` and `copy` name it for reports (the file's id is
// recording.tracks[track].id).
struct TrackPlacement {
    std::uint32_t track = 0;  // index into Recording::tracks
    std::uint32_t copy = 0;   // 0 for the recording as it is
    double timeShift = 0.0;   // seconds added to the track's sample times
    double dx = 0.0, dz = 0.0;  // metres added to its positions
};

// Every track once, unmoved: a replay of the recording as it is.
std::vector<TrackPlacement> placeAsRecorded(const Recording& recording);

struct CopySettings {
    std::uint32_t copies = 1;
    std::uint64_t seed = 1;  // the time shifts' (the same seed, the same crowd)
    double gap = 2.0;        // metres between neighbouring copies' extents
};

// Where and when one copy is.
struct CopyPlacement {
    double dx = 0.0, dz = 0.0;
    double timeShift = 0.0;  // in [0, period): its tracks are shifted by this, or by this - period
};

struct Tiling {
    std::uint32_t columns = 1, rows = 1;  // copy k in column k % columns, row k / columns
    double period = 0.0;                  // the recording's duration: shifts wrap around it
    std::vector<CopyPlacement> copies;
    // Copy-major: copy k's tracks are [k * trackCount, (k + 1) * trackCount), in the recording's order.
    std::vector<TrackPlacement> tracks;
};

// Tiles settings.copies copies of `recording`: a grid of ceil(sqrt(N)) columns, x across and z down,
// neighbours `gap` metres apart beyond the recording's extent, copy 0 where the recording is and
// unshifted. Copy k > 0 is shifted by a fraction of the duration drawn from (seed, k); a track whose
// shifted start would fall after the recording's end starts `period` earlier instead, so every copy
// is as busy at every moment of the recording as the recording is on average.
Tiling tileCopies(const Recording& recording, const CopySettings& settings);

}  // namespace replay
