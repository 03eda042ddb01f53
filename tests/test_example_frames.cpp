// examples/embed_headless draws the programs' frames: with --scene and --crowd-only its picture is
// crowd-render's for the same scene, count, method, start and frame (so bench/run_example.sh compares
// the cost of the very same frames), and it reports timings a script can parse.
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include "app/png_writer.h"
#include "support/gpu_test.h"
#include "support/run_program.h"

namespace {

// A PNG (crowd-render's) or binary PPM (the example's) as RGBA.
app::Rgba8Image readImage(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) return {};
    app::Rgba8Image image{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height),
                             std::vector<std::uint8_t>(data, data + std::size_t(width) * height * 4)};
    stbi_image_free(data);
    return image;
}

struct SceneFrame {
    const char* scene;
    const char* count;
    const char* method;
    const char* start;
};

// The last of three frames from `start`: crowd-render renders all three, the example one warm-up frame
// and two timed ones. Single-sampled (--aa off), as the example's own target is.
void expectExampleDrawsCrowdRendersFrame(const SceneFrame& frame) {
    const std::string name = std::string("example-frames-") + frame.scene + "-" + frame.method;
    const std::string png = test::artifactPath(name + ".png");
    const std::string common = std::string("--scene ") + frame.scene + " --method " + frame.method + " --start " +
                               frame.start;
    const test::ProgramResult program = test::runProgram(
        CROWD_RENDER_BINARY,
        common + " --count " + frame.count + " --aa off --frames 3 --size 256x144 --validation --out " + png);
    ASSERT_EQ(program.exitCode, 0) << program.err;

    const std::filesystem::path dir = test::artifactPath(name);
    std::filesystem::create_directories(dir);
    const test::ProgramResult example =
        test::runProgram(CROWD_EMBED_HEADLESS_BINARY,
                         common + " --count " + frame.count + " --crowd-only --warmup 1 " + dir.string() + " 256x144 2",
                         "CROWDGPU_VALIDATION=1");
    ASSERT_EQ(example.exitCode, 0) << example.err;

    std::smatch drawn;
    ASSERT_TRUE(std::regex_search(example.out, drawn, std::regex("([0-9]+) characters drawn"))) << example.out;
    EXPECT_GT(std::stoul(drawn[1]), 0u) << example.out;
    EXPECT_NE(example.out.find("timing frames=2 "), std::string::npos) << example.out;

    const app::Rgba8Image rendered = readImage(png), embedded = readImage((dir / "crowd.ppm").string());
    ASSERT_EQ(rendered.width, 256u);
    ASSERT_EQ(embedded.width, 256u);
    EXPECT_GE(test::fractionOfMatchingPixels(embedded, rendered, 1), 0.999) << name << ": see " << png << " and " << dir;
    if (!::testing::Test::HasFailure()) {
        std::filesystem::remove(png);
        std::filesystem::remove_all(dir);
    }
}

}  // namespace

// paper-fig4 flies over the crowd: at 7 s the camera has turned a sixth of its circle.
TEST(ExampleFrames, PaperFig4EqualsCrowdRender) {
    expectExampleDrawsCrowdRendersFrame({"paper-fig4", "2048", "compute", "7"});
}

// stress descends into the crowd: at 13 s it is part of the way down, between both ends of its path.
TEST(ExampleFrames, StressEqualsCrowdRender) {
    expectExampleDrawsCrowdRendersFrame({"stress", "4096", "two-pass", "13"});
}

// Without --crowd-only the host's boxes and ID pass are drawn too, and timed as a part of their own.
TEST(ExampleFrames, HostPassesAreTimedApart) {
    const std::filesystem::path dir = test::artifactPath("example-frames-host");
    std::filesystem::create_directories(dir);
    const test::ProgramResult example = test::runProgram(
        CROWD_EMBED_HEADLESS_BINARY, "--scene paper-fig4 --count 1024 " + dir.string() + " 128x72 2", "CROWDGPU_VALIDATION=1");
    ASSERT_EQ(example.exitCode, 0) << example.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "ids.pgm"));
    EXPECT_TRUE(std::regex_search(example.out, std::regex("passes_median_ms .* draw=[0-9.]+ id=[0-9.]+\n")))
        << example.out;
    std::filesystem::remove_all(dir);
}
