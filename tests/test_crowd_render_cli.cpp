// crowd-render as a user runs it: a small scene end to end, and one clear line for each bad value.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_program.h"

namespace {

const std::string kRender = CROWD_RENDER_BINARY;

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-cli-" + std::to_string(::getpid()) + "-" + name)).string();
}

// A bad invocation exits non-zero with exactly one line on stderr that mentions `mention`.
void expectOneLineError(const std::string& arguments, const std::string& mention, const std::string& environment = "") {
    const test::ProgramResult r = test::runProgram(kRender, arguments, environment);
    EXPECT_NE(r.exitCode, 0) << arguments;
    EXPECT_LT(r.exitCode, 124) << arguments << ": crashed or hung";
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << arguments << " printed:\n" << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << " printed:\n" << r.err;
    EXPECT_EQ(r.err.rfind("crowd-render: ", 0), 0u) << r.err;
}

}  // namespace

TEST(CrowdRenderCli, SmallSceneWritesPngAndJsonWithValidationSilent) {
    const std::string png = tempFile("small.png"), json = tempFile("small.json");
    const test::ProgramResult r = test::runProgram(
        kRender, "--count 4 --frames 3 --size 96x64 --validation --out " + png + " --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_GT(std::filesystem::file_size(png), 100u);
    std::ifstream file(json);
    const nlohmann::json j = nlohmann::json::parse(file);
    EXPECT_EQ(j["characters"], 4);
    EXPECT_EQ(j["method"], "two-pass");
    EXPECT_GT(j["fps"].get<double>(), 0.0);
    EXPECT_GT(j["median_frame_ms"].get<double>(), 0.0);
    for (const char* pass : {"motion", "cull", "palette", "skin", "copy", "draw"})
        EXPECT_TRUE(j["median_gpu_ms"].contains(pass)) << pass;
    EXPECT_EQ(j["animation"], "in-place, gpu animation");
    EXPECT_FALSE(j["device"].get<std::string>().empty());
    EXPECT_FALSE(j["driver"].get<std::string>().empty());
    std::filesystem::remove(png);
    std::filesystem::remove(json);
}

TEST(CrowdRenderCli, HelpAndDeviceListSucceed) {
    EXPECT_EQ(test::runProgram(kRender, "--help").exitCode, 0);
    const test::ProgramResult list = test::runProgram(kRender, "--list-devices");
    EXPECT_EQ(list.exitCode, 0);
    EXPECT_NE(list.out.find("0: "), std::string::npos) << list.out;
}

TEST(CrowdRenderCli, BadCountsAreRejected) {
    expectOneLineError("--count 0", "--count");
    expectOneLineError("--count -5", "--count");
    expectOneLineError("--count 12abc", "--count");
    expectOneLineError("--count 99999999999", "--count");
    expectOneLineError("--frames 0", "--frames");
    expectOneLineError("--count", "needs a value");
}

TEST(CrowdRenderCli, CountThatCannotFitInDeviceMemoryIsRejected) {
    expectOneLineError("--count 16777216 --frames 1 --out " + tempFile("huge.png"), "device memory");
}

TEST(CrowdRenderCli, UnknownModelAndMethodAreRejected) {
    expectOneLineError("--model dragon", "dragon");
    expectOneLineError("--method magic", "magic");
    expectOneLineError("--clip moonwalk --count 1 --frames 1 --out " + tempFile("clip.png"), "moonwalk");
    expectOneLineError("--bogus", "--bogus");
}

TEST(CrowdRenderCli, BadSizesAreRejected) {
    expectOneLineError("--size 0x100", "--size");
    expectOneLineError("--size 640", "--size");
    expectOneLineError("--size 640x", "--size");
    expectOneLineError("--size axb", "--size");
}

TEST(CrowdRenderCli, UnwritableOutputIsRejectedBeforeRendering) {
    expectOneLineError("--out /nonexistent-dir/x.png", "/nonexistent-dir/x.png");
    expectOneLineError("--json /nonexistent-dir/x.json --out " + tempFile("ok.png"), "/nonexistent-dir/x.json");
}

TEST(CrowdRenderCli, MissingVulkanDeviceIsReported) {
    expectOneLineError("--count 1 --frames 1 --out " + tempFile("nodev.png"), "Vulkan",
                       "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json");
    expectOneLineError("--device 99 --count 1 --frames 1 --out " + tempFile("nodev.png"), "--device");
    expectOneLineError("--device NoSuchGpu --count 1 --frames 1 --out " + tempFile("nodev.png"), "NoSuchGpu");
}

TEST(CrowdRenderCli, BadScenesAndLodSettingsAreRejected) {
    expectOneLineError("--scene nowhere", "nowhere");
    expectOneLineError("--lod-thresholds 50,150", "out of order");
    expectOneLineError("--lod-thresholds 100", "--lod-thresholds");
    expectOneLineError("--lod-thresholds 100,0", "out of order");
    expectOneLineError("--impostors on --impostor-threshold 60", "not below the LOD 2 threshold");
    expectOneLineError("--impostor-threshold 20 --lod-thresholds 100,15", "not below the LOD 2 threshold");
    expectOneLineError("--impostor-threshold 0", "above 0");
    expectOneLineError("--impostors maybe", "--impostors");
    expectOneLineError("--mesh-capacity 0", "too small");
    expectOneLineError("--lod maybe", "--lod");
    expectOneLineError("--lod-fade maybe", "--lod-fade");
    expectOneLineError("--impostor-blend maybe", "--impostor-blend");
    expectOneLineError("--far-crowd on", "--far-crowd");
    expectOneLineError("--cull sometimes", "--cull");
    expectOneLineError("--behaviour dance", "--behaviour");
    expectOneLineError("--animation quantum", "--animation");
    expectOneLineError("--lod-hysteresis 0.9", "--lod-hysteresis");
    expectOneLineError("--model soldier:0", "weight");
    expectOneLineError("--model soldier,,horse", "empty model name");
    expectOneLineError("--scene stress --count 16777216 --frames 1 --out " + tempFile("stress.png"), "device memory");
}

TEST(CrowdRenderCli, MixedSceneReportsCharactersPerLodAndTheCullPass) {
    const std::string png = tempFile("mixed.png"), json = tempFile("mixed.json");
    const test::ProgramResult r = test::runProgram(
        kRender, "--scene mixed --count 48 --frames 2 --size 96x64 --validation --out " + png + " --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream file(json);
    const nlohmann::json j = nlohmann::json::parse(file);
    EXPECT_EQ(j["scene"], "mixed");
    EXPECT_EQ(j["model"], "soldier+horse");
    EXPECT_EQ(j["characters"], 48);
    EXPECT_TRUE(j["median_gpu_ms"].contains("cull"));
    const double visible = j["median_visible_per_lod"][0].get<double>() + j["median_visible_per_lod"][1].get<double>() +
                           j["median_visible_per_lod"][2].get<double>();
    EXPECT_GT(visible, 0.0);
    EXPECT_LE(visible, 48.0);
    EXPECT_GT(j["median_triangles"].get<double>(), 0.0);
    std::filesystem::remove(png);
    std::filesystem::remove(json);
}

TEST(CrowdRenderCli, MarchAndMillScenesRunOnEitherAnimationPathWithValidationSilent) {
    for (const char* scene : {"march", "mill"})
        for (const char* animation : {"gpu", "cpu"}) {
            const std::string json = tempFile(std::string(scene) + "-" + animation + ".json");
            const test::ProgramResult r =
                test::runProgram(kRender, std::string("--scene ") + scene + " --count 32 --frames 3 --start 5 --size 96x64 "
                                          "--validation --animation " + animation + " --out /dev/null --json " + json);
            ASSERT_EQ(r.exitCode, 0) << r.err;
            EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
            std::ifstream file(json);
            const nlohmann::json j = nlohmann::json::parse(file);
            EXPECT_EQ(j["animation"], std::string(scene) + ", " + animation + " animation");
            std::filesystem::remove(json);
        }
}

namespace {

std::string readText(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// A run that failed to write `path` exits 1 with one line naming it.
void expectWriteFailure(const test::ProgramResult& r, const std::string& path) {
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("crowd-render: cannot write " + path + ": ", 0), 0u) << r.err;
}

}  // namespace

TEST(CrowdRenderCli, WritesToAFullDeviceFailNamingTheFile) {
    const std::string scene = "--count 4 --frames 1 --size 96x64";
    const test::ProgramResult png = test::runProgram(kRender, scene + " --out /dev/full");
    expectWriteFailure(png, "/dev/full");
    EXPECT_EQ(png.out.find("wrote"), std::string::npos) << png.out;
    expectWriteFailure(test::runProgram(kRender, scene + " --out /dev/null --json /dev/full"), "/dev/full");
}

TEST(CrowdRenderCli, OutputCutShortByAFullDiskLeavesNoFileAndKeepsTheOldOne) {
    // 320x240 of crowd is tens of KiB of PNG, the JSON about 1.2 KiB: a 1 KiB limit stops both part
    // way, as a full disk would, and leaves room for the summary on standard output (about 530 bytes).
    const std::string png = tempFile("full-disk.png"), json = tempFile("full-disk.json");
    const std::string limited = test::withFileSizeLimit(kRender, 2);
    const std::string scene = "--count 4 --frames 1 --size 320x240";
    expectWriteFailure(test::runProgram(limited, scene + " --out " + png), png);
    EXPECT_FALSE(std::filesystem::exists(png));
    expectWriteFailure(test::runProgram(limited, scene + " --out /dev/null --json " + json), json);
    EXPECT_FALSE(std::filesystem::exists(json));

    std::ofstream(png) << "the previous run's image";
    expectWriteFailure(test::runProgram(limited, scene + " --out " + png), png);
    EXPECT_EQ(readText(png), "the previous run's image");
    std::filesystem::remove(png);
    // Nothing else is left beside them either (the temporary files are removed).
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
        EXPECT_EQ(entry.path().filename().string().find("crowd-cli-" + std::to_string(::getpid()) + "-full-disk"),
                  std::string::npos)
            << entry.path();
}

TEST(CrowdRenderCli, AFileUnderDevShmCutShortKeepsTheOldOne) {
    // /dev/shm holds regular files: replaced whole or not at all, like any other folder's.
    if (::access("/dev/shm", W_OK) != 0) GTEST_SKIP() << "no writable /dev/shm";
    const std::string json = "/dev/shm/crowd-cli-" + std::to_string(::getpid()) + "-cut-short.json";
    std::ofstream(json) << "the previous run's JSON";
    const test::ProgramResult r = test::runProgram(test::withFileSizeLimit(kRender, 2),  // room for the summary
                                                   "--count 4 --frames 1 --size 64x64 --out /dev/null --json " + json);
    expectWriteFailure(r, json);
    EXPECT_EQ(r.err, "crowd-render: cannot write " + json + ": File too large\n");
    EXPECT_EQ(readText(json), "the previous run's JSON");
    std::filesystem::remove(json);
    for (const auto& entry : std::filesystem::directory_iterator("/dev/shm"))
        EXPECT_EQ(entry.path().filename().string().find("crowd-cli-" + std::to_string(::getpid())), std::string::npos)
            << entry.path();
}

TEST(CrowdRenderCli, JsonToStandardOutputFollowsTheSummaryWhole) {
    // Standard output is a file here (runProgram redirects it): the JSON is appended after the summary,
    // not written over it from offset 0, nor overwritten by it at exit.
    for (const char* path : {"/dev/stdout", "/proc/self/fd/1"}) {
        const test::ProgramResult r =
            test::runProgram(kRender, std::string("--count 4 --frames 1 --size 64x64 --out /dev/null --json ") + path);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::size_t json = r.out.find("\n{");
        ASSERT_NE(json, std::string::npos) << r.out;
        EXPECT_NE(r.out.substr(0, json).find("wrote /dev/null"), std::string::npos) << r.out;
        const nlohmann::json j = nlohmann::json::parse(r.out.substr(json + 1));
        EXPECT_EQ(j["characters"], 4) << path;
    }
}

TEST(CrowdRenderCli, ExportPoseCutShortLeavesNoFile) {
    const std::string obj = tempFile("full-disk.obj");
    expectWriteFailure(test::runProgram(test::withFileSizeLimit(kRender, 1), "--export-pose " + obj), obj);
    EXPECT_FALSE(std::filesystem::exists(obj));
    expectWriteFailure(test::runProgram(kRender, "--export-pose /dev/full"), "/dev/full");
}

TEST(CrowdRenderCli, EmptyValuesAreErrorsNotDefaults) {
    // '' used to mean "not given": --json '' skipped the JSON, --export-pose '' started a full render.
    for (const char* flag : {"--json", "--device", "--out", "--model", "--clip", "--asset-root", "--export-pose"})
        expectOneLineError(std::string(flag) + " '' --count 1 --frames 1 --out " + tempFile("empty.png"),
                           std::string(flag) + ": empty value");
    expectOneLineError("--export-pose " + tempFile("empty.obj") + " --time ''", "--time: empty value");
    expectOneLineError("--json= --count 1", "--json: empty value");
    EXPECT_FALSE(std::filesystem::exists(tempFile("empty.png")));
}

TEST(CrowdRenderCli, FlagsWithoutValuesRefuseOne) {
    expectOneLineError("--validation=no --count 1 --frames 1 --out " + tempFile("novalue.png"),
                       "--validation takes no value");
    expectOneLineError("--help=x", "--help takes no value");
    expectOneLineError("--list-devices=0", "--list-devices takes no value");
    expectOneLineError("--list-clips=yes", "--list-clips takes no value");
}

TEST(CrowdRenderCli, OneFrameReportsItsOwnTime) {
    const std::string json = tempFile("one-frame.json");
    const test::ProgramResult r =
        test::runProgram(kRender, "--count 1 --frames 1 --size 64x64 --out /dev/null --json " + json);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("(0.0 fps)"), std::string::npos) << r.out;
    std::ifstream file(json);
    const nlohmann::json j = nlohmann::json::parse(file);
    EXPECT_GT(j["fps"].get<double>(), 0.0);
    EXPECT_GT(j["median_frame_ms"].get<double>(), 0.0);
    EXPECT_EQ(j["frame_clock"], "one frame: CPU plan + animate + record + GPU passes");
    std::filesystem::remove(json);
}

TEST(CrowdRenderCli, StandardOutputThatCannotBeWrittenFailsTheRun) {
    // What a run prints is an output too: a clip list or a summary sent to a full disk is not success.
    const std::string toFullDevice = "sh -c 'exec \"$0\" \"$@\" >/dev/full' " + kRender;
    for (const char* arguments :
         {"--list-clips", "--help", "--count 1 --frames 1 --size 32x32 --out /dev/null"}) {
        const test::ProgramResult r = test::runProgram(toFullDevice, arguments);
        EXPECT_EQ(r.exitCode, 1) << arguments;
        // The reason is the failed write's own ("No space left on device") when the last write fails,
        // a generic "write error" when an earlier one did.
        EXPECT_EQ(r.err.rfind("crowd-render: cannot write standard output: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

TEST(CrowdRenderCli, AJsonToAStandardOutputThatCannotBeWrittenFailsInOneLine) {
    // One failure, one line: before, the JSON's failed write to /dev/stdout was reported, and then the
    // same stream again at exit ("cannot write standard output").
    const std::string toFullDevice = "sh -c 'exec \"$0\" \"$@\" >/dev/full' " + kRender;
    const test::ProgramResult r =
        test::runProgram(toFullDevice, "--count 1 --frames 1 --size 32x32 --out /dev/null --json /dev/stdout");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "crowd-render: cannot write /dev/stdout: No space left on device\n");
}

TEST(CrowdRenderCli, LateStartsRunInEveryKindOfScene) {
    // Living crowds go straight to the episode holding --start. Before, 64 milling characters at 1e6 s
    // replanned every segment from 0 s for minutes: the time limit fails such a run long before.
    for (const char* scene : {"mill", "march", "cavalry", "default"}) {
        const test::ProgramResult r = test::runProgram(
            kRender, std::string("--scene ") + scene + " --count 64 --start 1e6 --frames 2 --size 32x32 --validation "
                     "--out /dev/null", "", 60);
        EXPECT_EQ(r.exitCode, 0) << scene << ":\n" << r.err;
        EXPECT_EQ(r.err.find("validation"), std::string::npos) << scene << ":\n" << r.err;
    }
}

TEST(CrowdRenderCli, StartsOutsideTheirRangeAreRefusedInOneLine) {
    expectOneLineError("--start 2e9 --frames 1 --out /dev/null", "--start: 2e9 is outside 0..1000000000");
    expectOneLineError("--start -1 --frames 1 --out /dev/null", "--start: -1 is outside 0..1000000000");
    expectOneLineError("--start soon --frames 1 --out /dev/null", "--start: 'soon' is not a number");
}
