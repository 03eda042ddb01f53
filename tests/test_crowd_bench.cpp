// crowd-bench --quick as CI runs it: every method and model measured, every figure present in the CSV
// and JSON, validation silent. Nothing here asserts a speed.
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "skin/skinning_method.h"
#include "support/csv_file.h"
#include "support/run_program.h"

namespace {

const std::string kBench = CROWD_BENCH_BINARY;

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-bench-" + std::to_string(::getpid()) + "-" + name)).string();
}

}  // namespace

TEST(CrowdBench, QuickRunReportsEveryMethodModelAndSize) {
    const std::string csv = tempFile("quick.csv"), json = tempFile("quick.json");
    const test::ProgramResult r = test::runProgram(kBench, "--quick --validation --csv " + csv + " --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("Table 1 (soldier)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Table 1 (horse)"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("[24/24]"), std::string::npos) << "progress on stderr:\n" << r.err;

    std::ifstream csvFile(csv);
    std::string line;
    std::getline(csvFile, line);
    const std::vector<std::string> header = test::csvFields(line);
    std::set<std::string> seen;
    while (std::getline(csvFile, line)) {
        const std::vector<std::string> row = test::csvFields(line);
        ASSERT_EQ(row.size(), header.size()) << line;
        std::map<std::string, std::string> field;
        for (std::size_t i = 0; i < row.size(); ++i) field[header[i]] = row[i];
        EXPECT_EQ(field["status"], "ok") << line;
        for (const char* number : {"median_frame_ms", "p95_frame_ms", "fps", "gpu_draw_ms", "gpu_total_ms",
                                   "memory_bytes", "ratio_to_static"})
            EXPECT_GT(std::stod(field[number]), 0.0) << number << " in " << line;
        // GPU animation (the default): characters move and get palettes on the GPU, none on the CPU.
        EXPECT_NE(field["animation"].find("gpu animation"), std::string::npos) << line;
        EXPECT_EQ(std::stod(field["cpu_animate_ms"]), 0.0) << line;
        if (field["method"] != "static") {
            EXPECT_GT(std::stod(field["gpu_palette_ms"]), 0.0) << line;
            EXPECT_GT(std::stod(field["gpu_motion_ms"]), 0.0) << line;
        }
        EXPECT_FALSE(field["pass_clock"].empty());
        EXPECT_FALSE(field["device"].empty());
        EXPECT_FALSE(field["commit"].empty());
        const bool skins = field["method"] != "vs" && field["method"] != "vs-instanced" && field["method"] != "static";
        if (skins) {
            EXPECT_GT(std::stod(field["gpu_skin_ms"]), 0.0) << line;
        }
        if (field["method"] == "two-pass") {
            EXPECT_GT(std::stod(field["gpu_copy_ms"]), 0.0) << line;
        }
        seen.insert(field["model"] + "/" + field["method"] + "/" + field["characters"]);
    }
    for (const char* model : {"soldier", "horse"})
        for (skin::Method method : skin::allMethods())
            for (const char* count : {"1", "16"})
                EXPECT_TRUE(seen.count(std::string(model) + "/" + skin::methodName(method) + "/" + count))
                    << model << " " << skin::methodName(method) << " " << count;

    std::ifstream jsonFile(json);
    const nlohmann::json j = nlohmann::json::parse(jsonFile);
    EXPECT_FALSE(j["device"].get<std::string>().empty());
    EXPECT_FALSE(j["driver"].get<std::string>().empty());
    EXPECT_FALSE(j["date"].get<std::string>().empty());
    EXPECT_EQ(j["results"].size(), 24u);
    std::filesystem::remove(csv);
    std::filesystem::remove(json);
}

TEST(CrowdBench, BadValuesGiveOneLineErrors) {
    for (const char* arguments : {"--counts 0", "--counts 1,x", "--methods fast", "--pass-clock sundial", "--frames",
                                  "--csv /nonexistent-dir/x.csv", "--frame-log /nonexistent-dir/x.csv", "--counts 1,,2", "--counts 1,2,", "--csv ''",
                                  "--models soldier,bogus"}) {
        const test::ProgramResult r = test::runProgram(kBench, arguments);
        EXPECT_EQ(r.exitCode, 1) << arguments;
        // One line: a bad model is found before the device starts and the progress header is printed.
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << arguments << ":\n" << r.err;
    }
}

TEST(CrowdBench, FailedWritesExitOneNamingTheFile) {
    const std::string run = "--counts 1 --frames 1 --warmup 0 --size 32x32 --methods static --models soldier";
    for (const std::string output : {"--csv", "--json", "--frame-log"}) {
        const test::ProgramResult r = test::runProgram(kBench, run + " " + output + " /dev/full");
        EXPECT_EQ(r.exitCode, 1) << output << ":\n" << r.err;
        const std::string lastLine = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
        EXPECT_EQ(lastLine.rfind("crowd-bench: cannot write /dev/full: ", 0), 0u) << output << ":\n" << r.err;
    }
}

TEST(CrowdBench, LateStartsOfLivingCrowdsRunAndStartsOutsideTheRangeAreRefused) {
    // A milling crowd at 1e6 s is planned straight there (before: refused past 1e7 character-seconds).
    const test::ProgramResult late = test::runProgram(
        CROWD_BENCH_BINARY,
        "--behaviour mill --counts 16 --start 1e6 --frames 2 --warmup 0 --size 32x32 --methods compute --models soldier",
        "", 120);
    EXPECT_EQ(late.exitCode, 0) << late.err;
    const test::ProgramResult r = test::runProgram(CROWD_BENCH_BINARY, "--counts 16 --start 1e10", "", 60);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "crowd-bench: --start: 1e10 is outside 0..1000000000\n");
}
