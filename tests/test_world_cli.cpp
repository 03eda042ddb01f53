// The host's world through crowd-render's command line, as a user runs it (docs/host-driven.md): a recorded
// crowd in each text format replayed and exported (--trajectories, --export-states), checked against the
// file it came from; the churn, the agents and the hills, validation silent; a malformed file in one line.
#include <algorithm>
#include <cmath>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_program.h"

namespace {

const std::string kRender = CROWD_RENDER_BINARY;

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-world-" + std::to_string(::getpid()) + "-" + name)).string();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// One exported row: a person (the file's id) at a time, where its root stood.
struct StateRow {
    long id;
    double time, x, y, z;
};

std::vector<StateRow> readStates(const std::string& path) {
    std::ifstream file(path);
    std::string line;
    std::getline(file, line);
    EXPECT_EQ(line.rfind("id,copy,slot,time,x,y,z,heading,clip,rate", 0), 0u) << line;
    std::vector<StateRow> rows;
    while (std::getline(file, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream in(line);
        StateRow r{};
        long copy = 0, slot = 0;
        in >> r.id >> copy >> slot >> r.time >> r.x >> r.y >> r.z;
        rows.push_back(r);
    }
    return rows;
}

// Two people walking straight at 1.2 m/s for 4 s: person 1 along +x from (0, 0), person 2 along -x from
// (6, 3) (file metres), sampled at 25 fps; `row` writes one sample as its format does.
std::string twoWalkers(const std::string& header, const std::function<std::string(int id, int frame, double x, double y)>& row) {
    std::string text = header;
    for (int frame = 0; frame <= 100; ++frame) {
        const double t = frame / 25.0;
        text += row(1, frame, 1.2 * t, 0.0);
        text += row(2, frame, 6.0 - 1.2 * t, 3.0);
    }
    return text;
}

// Where the file puts person `id` at time t (the world: x = file x, z = -file y).
void expected(long id, double t, double& x, double& z) {
    x = id == 1 ? 1.2 * t : 6.0 - 1.2 * t;
    z = id == 1 ? 0.0 : -3.0;
}

// Replays `file` for 60 frames (1 s) with the states exported, drawn `delay` seconds behind the samples
// (at least their interval: an interpolation buffer); every living character's root is on its person's
// recorded path at the time drawn, within the walk's own sway, and both people are there.
void expectReplayFollowsTheFile(const std::string& file, double delay, const std::string& extra = "") {
    const std::string states = tempFile("states.csv"), png = tempFile("replay.png");
    const test::ProgramResult r = test::runProgram(
        kRender, "--trajectories " + file + " --drive-delay " + std::to_string(delay) + " " + extra + " --frames 60 --size 96x64 --validation --export-states " +
                     states + " --out " + png);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    const std::vector<StateRow> rows = readStates(states);
    std::map<long, int> seen;
    for (const StateRow& row : rows) {
        if (row.time < delay + 0.2) continue;  // entering: the first samples settle the gait
        double x = 0.0, z = 0.0;
        expected(row.id, row.time - delay, x, z);
        EXPECT_NEAR(row.x, x, 0.1) << file << ": person " << row.id << " at " << row.time << " s";
        EXPECT_NEAR(row.z, z, 0.1) << file << ": person " << row.id << " at " << row.time << " s";
        EXPECT_NEAR(row.y, 0.0, 1e-4) << "flat ground";
        ++seen[row.id];
    }
    EXPECT_EQ(seen.size(), 2u) << file;
    EXPECT_GE(seen[1], 15) << file;  // frames from delay + 0.2 s to 1 s
    std::filesystem::remove(states);
    std::filesystem::remove(png);
}

TEST(WorldCli, EachTextFormatIsReplayedOnItsRecordedPaths) {
    auto fixed = [](double v) { std::ostringstream s; s.precision(6); s << std::fixed << v; return s.str(); };
    // PeTrack: comments with the rate and units (cm), whitespace-separated id frame x y z.
    const std::string petrack = tempFile("walk.txt");
    writeText(petrack, twoWalkers("# framerate: 25 fps\n# id frame x/cm y/cm z/cm\n", [&](int id, int f, double x, double y) {
        return std::to_string(id) + "\t" + std::to_string(f) + "\t" + fixed(100 * x) + "\t" + fixed(100 * y) + "\t170.0\n";
    }));
    expectReplayFollowsTheFile(petrack, 0.1);
    // CSV with a time column (seconds) and columns in another order.
    const std::string csv = tempFile("walk.csv");
    writeText(csv, twoWalkers("x,y,ID,Time\n", [&](int id, int f, double x, double y) {
        return fixed(x) + "," + fixed(y) + "," + std::to_string(id) + "," + fixed(f / 25.0) + "\n";
    }));
    expectReplayFollowsTheFile(csv, 0.1);
    // ETH/UCY obsmat: frame id x z y vx vz vy in metres, a frame every 10 video frames at 25 fps (0.4 s:
    // drawn half a second behind).
    const std::string obsmat = tempFile("obsmat.txt");
    std::string text;
    for (int f = 0; f <= 100; f += 10)
        for (int id = 1; id <= 2; ++id) {
            double x = 0.0, z = 0.0;
            expected(id, f / 25.0, x, z);
            text += fixed(f) + " " + fixed(id) + " " + fixed(x) + " 0.0 " + fixed(-z) + " 0 0 0\n";
        }
    writeText(obsmat, text);
    expectReplayFollowsTheFile(obsmat, 0.5, "--trajectory-smoothing 0");
    for (const std::string& f : {petrack, csv, obsmat}) std::filesystem::remove(f);
}

TEST(WorldCli, TheSharedSimulationIsReplayedFromItsSqliteFile) {
    const std::filesystem::path file = std::filesystem::path(CROWD_SHARED_TRAJECTORIES_DIR) / "jupedsim-simulated.sqlite";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file << " (../shared/trajectories/): not run";
    const std::string states = tempFile("sim.csv"), png = tempFile("sim.png");
    const test::ProgramResult r = test::runProgram(
        kRender, "--trajectories " + file.string() + " --frames 30 --size 96x64 --validation --export-states " + states +
                     " --out " + png);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE((r.out + r.err).find("jupedsim, 30 people"), std::string::npos) << r.out << r.err;
    EXPECT_FALSE(readStates(states).empty());
    std::filesystem::remove(states);
    std::filesystem::remove(png);
}

TEST(WorldCli, AMalformedFileIsOneLineNamingItsLine) {
    const std::string file = tempFile("bad.txt"), png = tempFile("bad.png");
    writeText(file, "# framerate: 25 fps\n# id frame x/cm y/cm z/cm\n1 0 0.0 0.0 170\n1 1 abc 0.0 170\n");
    const test::ProgramResult r = test::runProgram(kRender, "--trajectories " + file + " --frames 2 --out " + png);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_LT(r.exitCode, 124) << "crashed or hung";
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(file + ":4: x (column 3) 'abc' is not a number"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png)) << "no picture of a run that never started";
    std::filesystem::remove(file);
}

TEST(WorldCli, ChurnAgentsAndHillsRunWithValidationSilent) {
    const std::string png = tempFile("world.png");
    for (const std::string world : {"--churn 10 --terrain hills", "--agents host --terrain hills", "--agents device",
                                    "--scene mill --churn 5 --method compute"}) {
        const test::ProgramResult r =
            test::runProgram(kRender, "--count 64 --frames 6 --size 96x64 --validation " + world + " --out " + png);
        EXPECT_EQ(r.exitCode, 0) << world << ":\n" << r.err;
        EXPECT_EQ(r.err.find("validation"), std::string::npos) << world << ":\n" << r.err;
        EXPECT_TRUE(std::filesystem::exists(png)) << world;
        std::filesystem::remove(png);
    }
}

TEST(WorldCli, ConflictingWorldFlagsAreOneLine) {
    const test::ProgramResult r = test::runProgram(kRender, "--agents host --churn 5 --frames 1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--churn"), std::string::npos) << r.err;
}

}  // namespace
