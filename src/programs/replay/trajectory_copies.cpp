#include "replay/trajectory_copies.h"

#include <algorithm>
#include <cmath>

namespace replay {
namespace {

// splitmix64 (Steele, Lea, Flood 2014): a well-mixed 64-bit value from (seed, k), so that shifts do
// not depend on the platform's std:: distributions.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// A fraction in [0, 1) for copy k.
double shiftFraction(std::uint64_t seed, std::uint32_t copy) {
    return static_cast<double>(mix(mix(seed) ^ copy) >> 11) * 0x1.0p-53;
}

}  // namespace

std::vector<TrackPlacement> placeAsRecorded(const Recording& recording) {
    std::vector<TrackPlacement> placements(recording.tracks.size());
    for (std::size_t i = 0; i < placements.size(); ++i) placements[i].track = static_cast<std::uint32_t>(i);
    return placements;
}

Tiling tileCopies(const Recording& recording, const CopySettings& settings) {
    Tiling tiling;
    const std::uint32_t count = std::max(settings.copies, 1u);
    tiling.columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    tiling.rows = (count + tiling.columns - 1) / tiling.columns;
    tiling.period = recording.info.duration();
    const Extent& extent = recording.info.extent;
    const double pitchX = extent.width() + settings.gap, pitchZ = extent.depth() + settings.gap;
    for (std::uint32_t k = 0; k < count; ++k) {
        CopyPlacement copy;
        copy.dx = pitchX * (k % tiling.columns);
        copy.dz = pitchZ * (k / tiling.columns);
        copy.timeShift = k == 0 ? 0.0 : shiftFraction(settings.seed, k) * tiling.period;
        tiling.copies.push_back(copy);
    }
    const double end = recording.info.endTime;
    tiling.tracks.reserve(static_cast<std::size_t>(count) * recording.tracks.size());
    for (std::uint32_t k = 0; k < count; ++k)
        for (std::uint32_t t = 0; t < recording.tracks.size(); ++t) {
            const CopyPlacement& copy = tiling.copies[k];
            const double start = recording.tracks[t].samples.front().time + copy.timeShift;
            const double shift = start > end ? copy.timeShift - tiling.period : copy.timeShift;
            tiling.tracks.push_back(TrackPlacement{t, k, shift, copy.dx, copy.dz});
        }
    return tiling;
}

}  // namespace replay
