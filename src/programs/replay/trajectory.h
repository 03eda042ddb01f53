#pragma once
// A recording of people walking, as read from a trajectory file (replay/trajectory_reader.h): one
// track per person, each a list of ground positions over time, in our world frame and seconds.
// Files put the ground in their own (x, y) plane; our y is up, so file (x, y) becomes world
// (x, -z): x = file x, z = -file y, a rotation of the plane about x by 90 degrees, not a mirror
// (a person walking counter-clockwise on the file's map still walks counter-clockwise seen from above).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace replay {

// Where a position was: at `time` seconds (the file's frame over its rate, so the file's first
// frame keeps its own time: frame 94 at 25 fps is 3.76 s) on the ground at world (x, z) metres.
struct Sample {
    double time = 0.0;
    double x = 0.0;
    double z = 0.0;
};

// One person: the file's id and the samples in time order, at least one, no two at the same time.
struct Track {
    std::int64_t id = 0;
    std::vector<Sample> samples;
};

// The ground rectangle the samples cover, metres. Empty (min > max) when there are none.
struct Extent {
    double minX = 0.0, maxX = -1.0;
    double minZ = 0.0, maxZ = -1.0;
    bool empty() const { return minX > maxX; }
    double width() const { return empty() ? 0.0 : maxX - minX; }
    double depth() const { return empty() ? 0.0 : maxZ - minZ; }
};

// Where a number the reader needed came from.
enum class Provenance {
    File,      // the file says it (a "# framerate:" line, a "/cm" column, SQLite metadata, seconds given)
    Flag,      // the user's --trajectory-fps / --trajectory-units
    Inferred,  // derived from the data (ETH/UCY frame steps over their 0.4 s annotation interval)
    Format,    // the format fixes it (JuPedSim, ETH/UCY and CSV are in metres)
};
const char* provenanceName(Provenance provenance);  // "file", "flag", "inferred", "format"

// What was read, for reports and for the user to check a reading (a wrong unit shows as a
// crowd 100 times too large, a wrong rate as people walking at 2.5 times their speed).
struct RecordingInfo {
    std::string path;
    std::string format;  // "petrack", "jupedsim", "obsmat", "csv"
    double fps = 0.0;    // frames per second used to turn frames into seconds; 0 when the file gives seconds
    Provenance fpsFrom = Provenance::File;
    std::string units;   // "m", "cm", "mm": the file's length unit
    Provenance unitsFrom = Provenance::Format;
    std::size_t people = 0;
    std::size_t rows = 0;  // samples read (one per row or database record)
    Extent extent;
    double startTime = 0.0;  // the earliest sample's time, seconds
    double endTime = 0.0;    // the latest's
    double duration() const { return endTime - startTime; }
};

// Tracks in ascending id order.
struct Recording {
    std::vector<Track> tracks;
    RecordingInfo info;
};

// The rectangle every track's samples cover.
Extent extentOf(const std::vector<Track>& tracks);

// Sets info's people, rows, extent and time span from the tracks (after reading or smoothing).
void summarize(Recording& recording);

}  // namespace replay
