// The shared recordings of ../shared/trajectories/ (README.md there; never copied here): read with
// their README's counts, at walking speeds that would show a unit or rate mistake, smoothed within
// 10 cm, and replayed in copies with every track and sample handed over once. Each test skips with a
// message when its file is absent.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "replay/path_smoothing.h"
#include "replay/replay_feed.h"
#include "replay/trajectory_copies.h"
#include "replay/trajectory_reader.h"

namespace {

using namespace replay;

struct SharedFile {
    const char* file;
    ReadOptions options;
    std::size_t people, rows;
    const char* format;
    double fps;
    Provenance fpsFrom;
    const char* units;
};

// The single-file CSV states no rate; its frames step by 10, and its own v_x, v_y columns match the
// positions' steps at 25 fps (SingleFileSpeedsMatchItsOwnVelocityColumns).
const SharedFile kSharedFiles[] = {
    {"juelich-bidirectional-corridor.txt", {}, 480, 120790, "petrack", 25.0, Provenance::File, "cm"},
    {"juelich-bottleneck.txt", {}, 75, 63110, "petrack", 25.0, Provenance::File, "m"},
    {"juelich-single-file.csv", {.fps = 25.0}, 53, 2391, "csv", 25.0, Provenance::Flag, "m"},
    {"jupedsim-simulated.sqlite", {}, 30, 8083, "jupedsim", 25.0, Provenance::File, "m"},
};

std::filesystem::path sharedFile(const char* name) { return std::filesystem::path(CROWD_SHARED_TRAJECTORIES_DIR) / name; }

#define SKIP_WITHOUT(path) \
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared recording " << (path) << " not present (see ../shared/trajectories/README.md)"

double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// Speeds between consecutive samples, m/s.
std::vector<double> sampleSpeeds(const Recording& r) {
    std::vector<double> speeds;
    for (const Track& t : r.tracks)
        for (std::size_t i = 1; i < t.samples.size(); ++i) {
            const Sample &a = t.samples[i - 1], &b = t.samples[i];
            speeds.push_back(std::hypot(b.x - a.x, b.z - a.z) / (b.time - a.time));
        }
    return speeds;
}

}  // namespace

TEST(TrajectoryRecordings, SharedFilesReadWithTheirReadmeCounts) {
    for (const SharedFile& shared : kSharedFiles) {
        const std::filesystem::path path = sharedFile(shared.file);
        SKIP_WITHOUT(path);
        const Recording r = readTrajectories(path.string(), shared.options);
        EXPECT_EQ(r.info.people, shared.people) << shared.file;
        EXPECT_EQ(r.info.rows, shared.rows) << shared.file;
        EXPECT_EQ(r.info.format, shared.format) << shared.file;
        EXPECT_EQ(r.info.fps, shared.fps) << shared.file;
        EXPECT_EQ(r.info.fpsFrom, shared.fpsFrom) << shared.file;
        EXPECT_EQ(r.info.units, shared.units) << shared.file;
        EXPECT_LT(std::max(r.info.extent.width(), r.info.extent.depth()), 30.0) << shared.file << ": a laboratory, not a unit mistake";
        std::cout << shared.file << ": " << r.info.people << " people, " << r.info.rows << " rows, " << r.info.startTime
                  << ".." << r.info.endTime << " s, x " << r.info.extent.minX << ".." << r.info.extent.maxX << " z "
                  << r.info.extent.minZ << ".." << r.info.extent.maxZ << " m, median speed " << median(sampleSpeeds(r))
                  << " m/s\n";
    }
}

TEST(TrajectoryRecordings, CorridorStartsAtItsFirstFrameAndWalksAtWalkingSpeed) {
    const std::filesystem::path path = sharedFile("juelich-bidirectional-corridor.txt");
    SKIP_WITHOUT(path);
    const Recording r = readTrajectories(path.string());
    EXPECT_DOUBLE_EQ(r.info.startTime, 94.0 / 25.0) << "the file's frames start at 94";
    const double speed = median(sampleSpeeds(r));  // 1.03 m/s: read in metres it would be 0.01, at 10 fps 0.41
    EXPECT_GT(speed, 0.5);
    EXPECT_LT(speed, 2.0);
}

TEST(TrajectoryRecordings, SimulationWalksAtWalkingSpeed) {
    const std::filesystem::path path = sharedFile("jupedsim-simulated.sqlite");
    SKIP_WITHOUT(path);
    const double speed = median(sampleSpeeds(readTrajectories(path.string())));  // 0.78 m/s
    EXPECT_GT(speed, 0.5);
    EXPECT_LT(speed, 2.0);
}

TEST(TrajectoryRecordings, BottleneckQueuesButEveryoneWalksOnceThrough) {
    // Most samples are of people waiting (median 0.14 m/s), so the median says nothing of units; each
    // person's fastest second does (median 1.0 m/s, once past the bottleneck).
    const std::filesystem::path path = sharedFile("juelich-bottleneck.txt");
    SKIP_WITHOUT(path);
    const Recording r = readTrajectories(path.string());
    std::vector<double> fastest;
    for (const Track& t : r.tracks) {
        double best = 0.0;
        for (std::size_t i = 0, j = 0; i < t.samples.size(); ++i) {
            while (j < t.samples.size() && t.samples[j].time - t.samples[i].time < 1.0) ++j;
            if (j == t.samples.size()) break;
            const Sample &a = t.samples[i], &b = t.samples[j];
            best = std::max(best, std::hypot(b.x - a.x, b.z - a.z) / (b.time - a.time));
        }
        fastest.push_back(best);
    }
    EXPECT_GT(median(fastest), 0.5);
    EXPECT_LT(median(fastest), 2.0);
}

TEST(TrajectoryRecordings, SingleFileSpeedsMatchItsOwnVelocityColumns) {
    // Dense single file moves at 0.2 m/s: no walking-speed band fits, but the file carries its own
    // velocities, which the positions read at 25 fps must match (at 10 fps they would be 2.5 times off).
    const std::filesystem::path path = sharedFile("juelich-single-file.csv");
    SKIP_WITHOUT(path);
    std::ifstream file(path);
    std::string line;
    std::getline(file, line);
    ASSERT_EQ(line, "ID,Frame,x,y,v_x,v_y");
    std::vector<double> stated;
    while (std::getline(file, line)) {
        std::stringstream fields(line);
        std::string field;
        std::vector<double> values;
        while (std::getline(fields, field, ',')) values.push_back(std::stod(field));
        stated.push_back(std::hypot(values[4], values[5]));
    }
    const double read = median(sampleSpeeds(readTrajectories(path.string(), {.fps = 25.0})));
    EXPECT_NEAR(read / median(stated), 1.0, 0.15) << "positions " << read << " m/s, the file's velocities " << median(stated);
}

TEST(TrajectoryRecordings, SmoothingAtTheDefaultWindowStaysWithinTenCentimetres) {
    for (const SharedFile& shared : kSharedFiles) {
        const std::filesystem::path path = sharedFile(shared.file);
        SKIP_WITHOUT(path);
        Recording r = readTrajectories(path.string(), shared.options);
        const SmoothingReport report = smoothPaths(r, kDefaultSmoothingWindow);
        std::cout << shared.file << ": smoothing over " << report.window << " s moves samples by " << report.meanDeviation
                  << " m on average, at most " << report.maxDeviation << " m (person " << report.maxId << " at "
                  << report.maxTime << " s)\n";
        EXPECT_LT(report.maxDeviation, 0.10) << shared.file;
        EXPECT_EQ(r.info.rows, shared.rows);
    }
}

TEST(TrajectoryRecordings, CorridorCopiesReplayEveryTrackOnce) {
    const std::filesystem::path path = sharedFile("juelich-bidirectional-corridor.txt");
    SKIP_WITHOUT(path);
    const Recording r = readTrajectories(path.string());
    const Tiling tiling = tileCopies(r, {.copies = 9, .seed = 1});
    ReplayFeed feed(r, tiling.tracks, {.linger = 0.5, .lookahead = 0.1});
    std::size_t started = 0, ended = 0, samples = 0, most = 0;
    for (double time = r.info.startTime; time < r.info.endTime + 2.0 * r.info.duration(); time += 1.0 / 30.0) {
        const FeedChanges& c = feed.advance(time);
        started += c.started.size();
        ended += c.ended.size();
        samples += c.samples.size();
        most = std::max(most, c.samples.size());
    }
    EXPECT_EQ(started, 9u * 480u);
    EXPECT_EQ(ended, 9u * 480u);
    EXPECT_EQ(samples, 9u * 120790u);
    EXPECT_LT(most, 9u * 480u) << "a frame delivers what came due, not every track";
}
