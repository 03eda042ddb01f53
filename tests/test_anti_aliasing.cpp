// Anti-aliasing (--aa): the colour pass multisampled and resolved into the picture, or the finished
// picture through the library's edge filter (fxaa). Against a 4x4 supersampled render of the same frame
// (4x the width and height, box-filtered down in linear light: app/image_downsample.h), 4 samples per
// pixel and the edge filter each come closer than one sample by a stated margin, for the default scene
// and for impostors (their coverage as a sample mask); the picture stays opaque; and --aa refuses, in
// one line, a name it does not know and a sample count the device lacks.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "app/anti_aliasing.h"
#include "app/image_difference.h"
#include "app/image_downsample.h"
#include "app/png_reader.h"
#include "support/gpu_test.h"
#include "support/run_program.h"

namespace {

const std::string kRender = CROWD_RENDER_BINARY;
const std::string kBench = CROWD_BENCH_BINARY;

std::string tempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-aa-" + std::to_string(::getpid()) + "-" + name)).string();
}

std::string deviceFlag() {
    const char* device = std::getenv("CROWD_TEST_DEVICE");
    return device ? std::string(" --device '") + device + "'" : "";
}

// crowd-render's last frame of `scene` at `size` with `aa`, validation on (it must stay silent).
app::Rgba8Image render(const std::string& scene, const std::string& size, const std::string& aa) {
    const std::string png = tempFile(aa + "-" + size + ".png");
    const test::ProgramResult r =
        test::runProgram(kRender, scene + " --frames 1 --validation --size " + size + " --aa " + aa + " --out " + png + deviceFlag());
    EXPECT_EQ(r.exitCode, 0) << scene << " --aa " << aa << ": " << r.err;
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    app::Rgba8Image image = app::readPng(png);
    std::filesystem::remove(png);
    return image;
}

struct Closeness {
    double off = 0.0, msaa4 = 0.0, fxaa = 0.0, both = 0.0;  // PSNR against the supersampled render, dB
    app::Rgba8Image multisampled, filtered;
};

// The scene at 256x144 without anti-aliasing, with 4 samples per pixel and with the edge filter, each
// against its render at 1024x576 box-filtered down; `withBoth`: and with msaa4+fxaa.
Closeness closenessToSupersampled(const std::string& scene, const std::string& name, bool withBoth = false) {
    const app::Rgba8Image reference = app::boxDownsample(render(scene, "1024x576", "off"), 4);
    const app::Rgba8Image off = render(scene, "256x144", "off");
    Closeness c;
    c.multisampled = render(scene, "256x144", "msaa4");
    c.filtered = render(scene, "256x144", "fxaa");
    c.off = app::compareImages(reference, off).psnr;
    c.msaa4 = app::compareImages(reference, c.multisampled).psnr;
    c.fxaa = app::compareImages(reference, c.filtered).psnr;
    if (withBoth) c.both = app::compareImages(reference, render(scene, "256x144", "msaa4+fxaa")).psnr;
    std::printf("%s: PSNR against the 4x4 supersampled render %.2f dB off, %.2f dB msaa4, %.2f dB fxaa\n",
                name.c_str(), c.off, c.msaa4, c.fxaa);
    if (withBoth) std::printf("%s: %.2f dB msaa4+fxaa\n", name.c_str(), c.both);
    if (c.msaa4 < c.off + 3.0 || c.fxaa < c.off + 1.0) {
        app::writePng(test::artifactPath(name + "-supersampled.png"), reference);
        app::writePng(test::artifactPath(name + "-off.png"), off);
        app::writePng(test::artifactPath(name + "-msaa4.png"), c.multisampled);
        app::writePng(test::artifactPath(name + "-fxaa.png"), c.filtered);
    }
    return c;
}

// A device that cannot do 4 samples (the Vulkan spec requires every device to) would skip.
bool hasFourSamples(const app::HostDevice& device) {
    return (device.properties.limits.framebufferColorSampleCounts & device.properties.limits.framebufferDepthSampleCounts &
            VK_SAMPLE_COUNT_4_BIT) != 0;
}

}  // namespace

using test::GpuTest;

TEST_F(GpuTest, AntiAliasingBringsTheDefaultSceneTowardsItsSupersampledRender) {
    if (!hasFourSamples(*device)) GTEST_SKIP() << "no 4-sample colour and depth on this device";
    // Lavapipe: 27.2 dB off, 34.5 dB msaa4 (+7.3 dB), 30.3 dB fxaa (+3.1 dB), 34.5 dB msaa4+fxaa; the
    // margins asked are under half those.
    const Closeness c = closenessToSupersampled("--scene default", "default-scene", true);
    EXPECT_GT(c.msaa4, c.off + 3.0);
    EXPECT_GT(c.fxaa, c.off + 1.5);
    // Both: the samples resolved into the image the filter reads (validation silent on that path too).
    EXPECT_GT(c.both, c.off + 3.0);
}

TEST_F(GpuTest, AntiAliasingBringsImpostorsTowardsTheirSupersampledRender) {
    if (!hasFourSamples(*device)) GTEST_SKIP() << "no 4-sample colour and depth on this device";
    // Inside a crowd of impostors drawn by the hardware (their coverage as a sample mask at 4 samples, cut
    // at half coverage at 1; in compute, multisampled frames draw them whole: test_compute_raster.cpp).
    // Without props: a flag carrier's impostor has no flag while its supersampled mesh does (docs/props.md),
    // an error no anti-aliasing removes.
    // Lavapipe: 30.44 dB off, 34.05 dB msaa4 (+3.6 dB), 32.76 dB fxaa (+2.3 dB); the margins asked are
    // under two thirds of those.
    const Closeness c = closenessToSupersampled(
        "--scene stress --count 4000 --start 20 --impostors on --method compute --props off --raster hardware",
        "impostors");
    EXPECT_GT(c.msaa4, c.off + 2.0);
    EXPECT_GT(c.fxaa, c.off + 1.2);
    // The coverage goes to samples covered, not into the picture's alpha; and with the sky in place of a
    // colour clear, every sample's alpha is written by what covers it. The edge filter keeps alpha.
    for (const app::Rgba8Image* picture : {&c.multisampled, &c.filtered}) {
        const std::vector<std::uint8_t>& p = picture->pixels;
        std::size_t translucent = 0;
        for (std::size_t i = 3; i < p.size(); i += 4) translucent += p[i] != 255;
        EXPECT_EQ(translucent, 0u) << "pixels whose alpha is not 255";
    }
}

TEST_F(GpuTest, AaRefusesUnknownNamesAndSampleCountsTheDeviceLacksInOneLine) {
    auto expectOneLine = [](const std::string& program, const std::string& arguments, const std::string& mention) {
        const test::ProgramResult r = test::runProgram(program, arguments + deviceFlag());
        EXPECT_EQ(r.exitCode, 1) << arguments << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << arguments << " printed:\n" << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << " printed:\n" << r.err;
    };
    for (const std::string& program : {kRender, kBench})
        expectOneLine(program, "--aa msaa16", "--aa: 'msaa16' is not off, msaa2, msaa4, msaa8, fxaa or msaaN+fxaa");
#ifdef CROWD_VIEW_BINARY
    expectOneLine(CROWD_VIEW_BINARY, "--aa on", "--aa: 'on' is not off, msaa2, msaa4, msaa8, fxaa or msaaN+fxaa");
#endif
    // The first count this device lacks (lavapipe: 2), named with the device and what it can do.
    const VkSampleCountFlags counts =
        device->properties.limits.framebufferColorSampleCounts & device->properties.limits.framebufferDepthSampleCounts;
    for (VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_2_BIT, VK_SAMPLE_COUNT_4_BIT, VK_SAMPLE_COUNT_8_BIT}) {
        if (counts & samples) continue;
        const std::string aa = app::antiAliasingName(samples);
        const std::string words = "--aa " + aa + ": " + device->description.name + " cannot render " +
                                  std::to_string(samples) + " samples per pixel (it can: ";
        expectOneLine(kRender, "--count 4 --frames 1 --size 64x64 --out /dev/null --aa " + aa, words);
        expectOneLine(kBench, "--quick --methods compute --aa " + aa, words);
        return;
    }
    std::printf("this device renders 2, 4 and 8 samples: no count to refuse\n");
}
