#include "replay/trajectory.h"

#include <algorithm>
#include <limits>

namespace replay {

const char* provenanceName(Provenance provenance) {
    switch (provenance) {
        case Provenance::File: return "file";
        case Provenance::Flag: return "flag";
        case Provenance::Inferred: return "inferred";
        case Provenance::Format: return "format";
    }
    return "?";
}

Extent extentOf(const std::vector<Track>& tracks) {
    Extent extent;
    extent.minX = extent.minZ = std::numeric_limits<double>::infinity();
    extent.maxX = extent.maxZ = -std::numeric_limits<double>::infinity();
    for (const Track& track : tracks)
        for (const Sample& s : track.samples) {
            extent.minX = std::min(extent.minX, s.x);
            extent.maxX = std::max(extent.maxX, s.x);
            extent.minZ = std::min(extent.minZ, s.z);
            extent.maxZ = std::max(extent.maxZ, s.z);
        }
    if (extent.minX > extent.maxX) return Extent{};
    return extent;
}

void summarize(Recording& recording) {
    RecordingInfo& info = recording.info;
    info.people = recording.tracks.size();
    info.rows = 0;
    info.startTime = info.endTime = 0.0;
    bool first = true;
    for (const Track& track : recording.tracks) {
        info.rows += track.samples.size();
        if (track.samples.empty()) continue;
        const double start = track.samples.front().time, end = track.samples.back().time;
        info.startTime = first ? start : std::min(info.startTime, start);
        info.endTime = first ? end : std::max(info.endTime, end);
        first = false;
    }
    info.extent = extentOf(recording.tracks);
}

}  // namespace replay
