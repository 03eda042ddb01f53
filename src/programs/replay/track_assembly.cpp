#include "replay/track_assembly.h"

#include <algorithm>
#include <map>

#include "app/error.h"
#include "app/number_text.h"

namespace replay {

Locator lineLocator(const std::string& path) {
    return [path](std::uint64_t line) { return path + ":" + std::to_string(line); };
}

void sortRows(std::vector<Row>& rows, const Locator& locate, const char* whenName, const char* whereName) {
    // `where` breaks ties so that of two equal rows the one earlier in the file comes first.
    std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
        if (a.id != b.id) return a.id < b.id;
        if (a.when != b.when) return a.when < b.when;
        return a.where < b.where;
    });
    // Of several repeats the one a reader meets first going down the file is reported.
    const Row* repeat = nullptr;
    const Row* original = nullptr;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const Row& a = rows[i - 1];
        const Row& b = rows[i];
        if (a.id != b.id || a.when != b.when) continue;
        if (!repeat || b.where < repeat->where) {
            repeat = &b;
            original = &a;
        }
    }
    if (repeat)
        throw app::Error(locate(repeat->where) + ": person " + std::to_string(repeat->id) + " has " + whenName + " " +
                         app::formatNumber(repeat->when) + " twice (also at " + whereName + " " +
                         std::to_string(original->where) + ")");
}

double mostCommonStep(const std::vector<Row>& rows) {
    std::map<double, std::size_t> counts;
    for (std::size_t i = 1; i < rows.size(); ++i)
        if (rows[i].id == rows[i - 1].id) ++counts[rows[i].when - rows[i - 1].when];
    double step = 0.0;
    std::size_t best = 0;
    for (const auto& [value, count] : counts)  // ascending: the smallest of equally common steps wins
        if (count > best) {
            step = value;
            best = count;
        }
    return step;
}

std::vector<Track> assembleTracks(const std::vector<Row>& rows, double whenPerSecond, double unitsPerMetre) {
    std::vector<Track> tracks;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (i == 0 || rows[i].id != rows[i - 1].id) tracks.push_back(Track{rows[i].id, {}});
        tracks.back().samples.push_back(Sample{rows[i].when / whenPerSecond, rows[i].x / unitsPerMetre, -rows[i].y / unitsPerMetre});
    }
    return tracks;
}

Rate chooseRate(const std::string& path, const ReadOptions& options, double fileFps, Provenance fileFrom,
                const std::string& missing, bool needed) {
    if (options.fps > 0.0) return {options.fps, Provenance::Flag};
    if (fileFps > 0.0) return {fileFps, fileFrom};
    if (needed) throw app::Error(path + ": " + missing + "; give " + kFpsFlag);
    return {0.0, fileFrom};
}

Unit chooseUnits(const std::string& path, const ReadOptions& options, Units fileUnits, Provenance fileFrom,
                 const std::string& missing, bool needed) {
    if (options.units != Units::Unset) return {options.units, Provenance::Flag};
    if (fileUnits != Units::Unset) return {fileUnits, fileFrom};
    if (needed) throw app::Error(path + ": " + missing + "; give " + kUnitsFlag);
    return {Units::Unset, fileFrom};
}

Recording makeRecording(const std::string& path, Format format, const std::vector<Row>& rows, Rate rate, Unit unit) {
    Recording recording;
    // Files that give seconds have no rate (fps 0): their `when` is the time already.
    recording.tracks = assembleTracks(rows, rate.fps > 0.0 ? rate.fps : 1.0, unitsPerMetre(unit.units));
    RecordingInfo& info = recording.info;
    info.path = path;
    info.format = formatName(format);
    info.fps = rate.fps;
    info.fpsFrom = rate.from;
    info.units = unitsName(unit.units);
    info.unitsFrom = unit.from;
    summarize(recording);
    return recording;
}

}  // namespace replay
