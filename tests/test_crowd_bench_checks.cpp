// crowd-bench decides before it measures: a count the host cannot hold is refused in one line, rows
// the device cannot run are skipped up front (naming the clock that would have timed them), a run
// that measured nothing fails, --palette writes its CSV, its flags parse as crowd-render's do and its
// help states crowd-render's defaults, and --frame-log holds the frames the summary's figures come from.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
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
#include "support/csv_file.h"
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
    const std::vector<std::string> rows = test::readLines(csv);
    ASSERT_EQ(rows.size(), 3u) << "--palette --csv wrote no CSV";
    EXPECT_EQ(test::csvField(rows, 1, "status"), "ok");
    EXPECT_EQ(test::csvField(rows, 1, "gpu_clock"), "fence wall clock");
    EXPECT_EQ(test::csvField(rows, 2, "status"), "skipped");
    EXPECT_EQ(test::csvField(rows, 2, "gpu_clock"), "fence wall clock");
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
    const std::vector<std::string> rows = test::readLines(csv);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(test::csvField(rows, 1, "status"), "skipped");
    EXPECT_EQ(test::csvField(rows, 1, "pass_clock"), "fence wall clock");
    std::filesystem::remove(csv);
}

TEST(CrowdBenchChecks, FlagsParseAsCrowdRendersDo) {
    const std::string csv = tempFile("equals.csv");
    const test::ProgramResult r = test::runProgram(
        kBench, "--counts=1 --methods=static --models=soldier --frames=1 --warmup=0 --size=32x32 --lod-thresholds=20,10" +
                    deviceFlag() + " --csv=" + csv);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readLines(csv).size(), 2u);
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

// Every flag both programs document states the same default in each help, but for --frames (the
// bench measures 60 frames, crowd-render renders 30). crowd-bench's --far-crowd said "off" after the
// default became "average".
TEST(CrowdBenchChecks, HelpStatesCrowdRendersDefaults) {
    auto defaults = [](const std::string& help) {
        std::map<std::string, std::string> found;  // flag -> the text after "(default "
        std::string flag, paragraph;
        auto close = [&] {
            const std::size_t at = paragraph.find("(default ");
            if (!flag.empty() && at != std::string::npos)
                found[flag] = paragraph.substr(at + 9, paragraph.find_first_of(");", at) - at - 9);
        };
        std::istringstream lines(help);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("  --", 0) == 0) {
                close();
                flag = line.substr(2, line.find(' ', 2) - 2);
                paragraph = line;
            } else if (line.rfind("      ", 0) == 0) {
                paragraph.append(" ").append(line, line.find_first_not_of(' '), std::string::npos);
            }
        }
        close();
        return found;
    };
    const test::ProgramResult bench = test::runProgram(kBench, "--help");
    const test::ProgramResult render = test::runProgram(CROWD_RENDER_BINARY, "--help");
    ASSERT_EQ(bench.exitCode, 0);
    ASSERT_EQ(render.exitCode, 0);
    const std::map<std::string, std::string> benchDefaults = defaults(bench.out), renderDefaults = defaults(render.out);
    std::size_t compared = 0;
    for (const auto& [flag, value] : benchDefaults) {
        const auto other = renderDefaults.find(flag);
        if (other == renderDefaults.end() || flag == "--frames") continue;
        EXPECT_EQ(value, other->second) << flag;
        ++compared;
    }
    EXPECT_GE(compared, 12u) << "the helps' layout changed: too few defaults found to compare";
}

// The frame log (--frame-log): a row per measured frame of each configuration, at the scene times the
// frames were rendered at; its intervals are what the summary's median and p95 are taken over.
TEST(CrowdBenchChecks, TheFrameLogHoldsTheFramesTheSummaryComesFrom) {
    const std::string log = tempFile("frames.csv"), csv = tempFile("summary.csv");
    const test::ProgramResult r = test::runProgram(
        kBench, "--counts 16 --methods compute,static --models soldier --frames 7 --warmup 3 --start 2 --size 32x32" +
                    deviceFlag() + " --frame-log " + log + " --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<std::string> rows = test::readLines(log), summary = test::readLines(csv);
    ASSERT_EQ(rows.size(), 1u + 2u * 7u);
    ASSERT_EQ(summary.size(), 3u);
    for (std::size_t config = 0; config < 2; ++config) {
        std::vector<double> intervals, shadowTriangles;
        for (std::size_t i = 0; i < 7; ++i) {
            const std::size_t row = 1 + config * 7 + i;
            EXPECT_EQ(test::csvField(rows, row, "method"), test::csvField(summary, 1 + config, "method"));
            EXPECT_EQ(test::csvField(rows, row, "frame"), std::to_string(i));
            // Frame k of a run is rendered at start + k / 60 s; the log starts after the warm-up.
            EXPECT_NEAR(std::stod(test::csvField(rows, row, "scene_seconds")), 2.0 + (3.0 + i) / 60.0, 1e-4);
            double passes = 0.0;
            for (const char* pass : {"cull", "draw", "shadow", "motion"}) {
                const double ms = std::stod(test::csvField(rows, row, std::string("gpu_") + pass + "_ms"));
                EXPECT_GE(ms, 0.0) << pass;
                passes += ms;
            }
            EXPECT_GE(std::stod(test::csvField(rows, row, "gpu_total_ms")), passes * 0.999);
            intervals.push_back(std::stod(test::csvField(rows, row, "interval_ms")));
            shadowTriangles.push_back(std::stod(test::csvField(rows, row, "shadow_triangles")));
            EXPECT_EQ(test::csvField(rows, row, "shadow_impostors"), "0");  // no impostors in this crowd
        }
        // The shadow pass's casters, frame by frame: the summary's median is theirs.
        std::sort(shadowTriangles.begin(), shadowTriangles.end());
        EXPECT_GT(shadowTriangles[3], 0.0);
        EXPECT_EQ(shadowTriangles[3], std::stod(test::csvField(summary, 1 + config, "shadow_triangles")));
        // The first measured frame's interval is the last warm-up frame's: every row has one.
        EXPECT_TRUE(std::all_of(intervals.begin(), intervals.end(), [](double ms) { return ms > 0.0; }));
        std::sort(intervals.begin(), intervals.end());
        EXPECT_NEAR(intervals[3], std::stod(test::csvField(summary, 1 + config, "median_frame_ms")), 1e-3 * intervals[3]);
    }
    std::filesystem::remove(log);
    std::filesystem::remove(csv);
}

// --palette measures bone palettes, not frames: before, --frame-log with it wrote no file and exited 0.
TEST(CrowdBenchChecks, AFrameLogWithPaletteIsRefusedInOneLine) {
    const std::string log = tempFile("palette-frames.csv");
    const test::ProgramResult r = test::runProgram(kBench, "--palette --counts 16" + kSmall + deviceFlag() + " --frame-log " + log);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err,
              "crowd-bench: --frame-log: --palette measures bone palettes, not frames; there is no frame log to write\n");
    EXPECT_FALSE(std::filesystem::exists(log));
}

}  // namespace
