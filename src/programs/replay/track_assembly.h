#pragma once
// From a file's rows to tracks, the same for every format: rows are grouped by person and sorted by
// frame (files list them by person or by frame, and a row out of order is taken, not refused); two
// rows of one person at one frame are an error, since no position of the two is the right one.
// Then frames become seconds and the file's ground (x, y) in its unit becomes world (x, z) metres.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "replay/trajectory.h"
#include "replay/trajectory_options.h"

namespace replay {

// One row as read: the person, when (a frame, or seconds for files that give them), the file's
// ground position in its unit, and where the row is in the file (a line, a database row id).
struct Row {
    std::int64_t id = 0;
    double when = 0.0;
    double x = 0.0, y = 0.0;
    std::uint64_t where = 0;
};

// Says where a row is for an error: "PATH:LINE" for text, "PATH: trajectory_data rowid N" for SQLite.
using Locator = std::function<std::string(std::uint64_t where)>;
Locator lineLocator(const std::string& path);  // "PATH:LINE"

// Sorts rows by person, then by `when`. Throws app::Error "LOCATION: person 3 has frame 12 twice
// (also at line 8)" at the later row of the repeat that comes first in the file; `whenName` is "frame" or
// "time", `whereName` "line" or "rowid".
void sortRows(std::vector<Row>& rows, const Locator& locate, const char* whenName, const char* whereName);

// The most common step between a person's consecutive frames over sorted rows (the smallest of
// equally common ones); 0 when no person has two rows.
double mostCommonStep(const std::vector<Row>& rows);

// Tracks from sorted rows, ascending by id: time = when / whenPerSecond, world x = x / unitsPerMetre,
// z = -y / unitsPerMetre (divisions, so that 94 / 25 and -554.56 / 100 are the nearest doubles).
std::vector<Track> assembleTracks(const std::vector<Row>& rows, double whenPerSecond, double unitsPerMetre);

// The rate to use: the flag's when given, else the file's (> 0), else app::Error "PATH: MISSING; give
// --trajectory-fps". `needed` false (no rows) returns what is known without failing.
struct Rate {
    double fps = 0.0;
    Provenance from = Provenance::File;
};
Rate chooseRate(const std::string& path, const ReadOptions& options, double fileFps, Provenance fileFrom,
                const std::string& missing, bool needed);

// The unit likewise: the flag's, else the file's (`fileUnits`, Unset when the file names none), else
// app::Error "PATH: MISSING; give --trajectory-units".
struct Unit {
    Units units = Units::Unset;
    Provenance from = Provenance::File;
};
Unit chooseUnits(const std::string& path, const ReadOptions& options, Units fileUnits, Provenance fileFrom,
                 const std::string& missing, bool needed);

// A recording of the sorted rows, its info filled in.
Recording makeRecording(const std::string& path, Format format, const std::vector<Row>& rows, Rate rate, Unit unit);

}  // namespace replay
