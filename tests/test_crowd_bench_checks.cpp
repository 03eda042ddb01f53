// crowd-bench decides before it measures: a count the host cannot hold is refused in one line, rows
// the device cannot run are skipped up front (naming the clock that would have timed them), a run
// that measured nothing fails, --palette writes its CSV, and its flags parse as crowd-render's do.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/host_device.h"
#include "app/host_memory.h"
#include "app/crowd_app.h"
#include "app/scene_presets.h"
#include "crowd/host_memory.h"
#include "gpu/vulkan_context.h"
#include "render/geometry_pool.h"
#include "support/run_program.h"

namespace {

const std::string kBench = CROWD_BENCH_BINARY;
const std::string kSmall = " --models soldier --frames 1 --warmup 0 --size 32x32";

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-bench-checks-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

std::string deviceFlag() {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    return device ? std::string(" --device '") + device + "'" : "";
}

std::uint64_t storageRange() {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    return app::HostDevice({false, device ? device : "", {}, false}).properties.limits.maxStorageBufferRange;
}

std::vector<std::string> lines(const std::string& path) {
    std::ifstream file(path);
    std::vector<std::string> result;
    for (std::string line; std::getline(file, line);) result.push_back(line);
    return result;
}

// The value of column `name` in row `row` (1: the first data row) of a CSV without commas in quotes
// before that column.
std::string column(const std::vector<std::string>& csv, std::size_t row, const std::string& name) {
    auto split = [](const std::string& line) {
        std::vector<std::string> fields;
        std::stringstream stream(line);
        for (std::string f; std::getline(stream, f, ',');) fields.push_back(f);
        return fields;
    };
    const std::vector<std::string> header = split(csv.at(0)), fields = split(csv.at(row));
    const auto at = std::find(header.begin(), header.end(), name);
    return at == header.end() || static_cast<std::size_t>(at - header.begin()) >= fields.size()
               ? "<no " + name + ">"
               : fields[at - header.begin()];
}

TEST(CrowdBenchChecks, ACrowdTheHostCannotHoldIsRefusedInOneLineBeforeAnythingIsAllocated) {
    const app::CrowdModels soldier = app::loadModels("soldier", 1);
    if (crowdgpu::hostBytesNeeded(soldier.models, app::kMaxCharacters, true) <= app::availableHostBytes())
        GTEST_SKIP() << "this machine has the host memory for the largest crowd";
    const auto start = std::chrono::steady_clock::now();
    const test::ProgramResult r =
        test::runProgram(kBench, "--palette --counts " + std::to_string(app::kMaxCharacters) + kSmall + deviceFlag());
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("of host memory"), std::string::npos) << r.err;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(CrowdBenchChecks, PaletteRowsThatCannotRunAreSkippedBeforeMeasuringAndARunOfOnlySkipsFails) {
    // More soldiers than one storage binding holds bones for (1,008 bytes each at least).
    const std::uint64_t over = storageRange() / 1008 + 1;
    if (over > app::kMaxCharacters) GTEST_SKIP() << "this device binds bones for every crowd size";
    const std::string csv = tempFile("palette-skipped.csv");
    const test::ProgramResult r = test::runProgram(
        kBench, "--palette --pass-clock fence --counts 16," + std::to_string(over) + kSmall + deviceFlag() + " --csv " + csv);
    EXPECT_EQ(r.exitCode, 0) << r.err;  // the row of 16 was measured
    // Decided up front: the skip is reported before the first row is measured.
    EXPECT_LT(r.err.find(std::to_string(over) + " characters: skipped"), r.err.find("palettes: 16 characters")) << r.err;
    const std::vector<std::string> rows = lines(csv);
    ASSERT_EQ(rows.size(), 3u) << "--palette --csv wrote no CSV";
    EXPECT_EQ(column(rows, 1, "status"), "ok");
    EXPECT_EQ(column(rows, 1, "gpu_clock"), "fence wall clock");
    EXPECT_EQ(column(rows, 2, "status"), "skipped");
    EXPECT_EQ(column(rows, 2, "gpu_clock"), "fence wall clock");
    std::filesystem::remove(csv);

    const test::ProgramResult only = test::runProgram(kBench, "--palette --counts " + std::to_string(over) + kSmall + deviceFlag());
    EXPECT_EQ(only.exitCode, 1) << only.err;
    EXPECT_NE(only.err.find("crowd-bench: every configuration was skipped"), std::string::npos) << only.err;
}

TEST(CrowdBenchChecks, SkippedRowsNameTheClockThatWouldHaveTimedThemAndARunOfOnlySkipsFails) {
    // compute binds its skinned positions whole: more soldiers than that binding holds (810 vertices of 16 bytes).
    const std::uint64_t over = storageRange() / (16u * 810u) + 1;
    if (over > app::kMaxCharacters) GTEST_SKIP() << "this device binds skinned vertices for every crowd size";
    const std::string csv = tempFile("skipped.csv");
    const test::ProgramResult r = test::runProgram(kBench, "--pass-clock fence --methods compute --counts " +
                                                               std::to_string(over) + kSmall + deviceFlag() + " --csv " + csv);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("crowd-bench: every configuration was skipped (first: soldier compute x " + std::to_string(over)),
              std::string::npos)
        << r.err;
    const std::vector<std::string> rows = lines(csv);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(column(rows, 1, "status"), "skipped");
    EXPECT_EQ(column(rows, 1, "pass_clock"), "fence wall clock");
    std::filesystem::remove(csv);
}

TEST(CrowdBenchChecks, FlagsParseAsCrowdRendersDo) {
    const std::string csv = tempFile("equals.csv");
    const test::ProgramResult r = test::runProgram(
        kBench, "--counts=1 --methods=static --models=soldier --frames=1 --warmup=0 --size=32x32 --lod-thresholds=20,10" +
                    deviceFlag() + " --csv=" + csv);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lines(csv).size(), 2u);
    std::filesystem::remove(csv);
    for (const char* arguments : {"--quick=yes", "--count 4", "--out x.png", "--impostors on --impostor-threshold 60"}) {
        const test::ProgramResult bad = test::runProgram(kBench, arguments);
        EXPECT_EQ(bad.exitCode, 1) << arguments;
        EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << arguments << ":\n" << bad.err;
    }
}

TEST(CrowdBenchChecks, HelpNamesEveryScene) {
    const test::ProgramResult help = test::runProgram(kBench, "--help");
    EXPECT_EQ(help.exitCode, 0);
    // --scene's paragraph, up to the next flag.
    const std::size_t start = help.out.find("--scene NAME");
    ASSERT_NE(start, std::string::npos) << help.out;
    const std::string scenes = help.out.substr(start, help.out.find("\n  --", start) - start);
    auto namesWord = [&](const std::string& word) {  // as a whole word: "mixed", not "mix"
        auto partOfName = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; };
        for (std::size_t at = scenes.find(word); at != std::string::npos; at = scenes.find(word, at + 1))
            if ((at == 0 || !partOfName(scenes[at - 1])) &&
                (at + word.size() == scenes.size() || !partOfName(scenes[at + word.size()])))
                return true;
        return false;
    };
    for (const app::ScenePreset& preset : app::scenePresets())
        EXPECT_TRUE(namesWord(preset.name)) << preset.name << " missing from:\n" << scenes;
}

}  // namespace
