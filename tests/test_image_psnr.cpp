// image-psnr, the benchmark scripts' picture comparison: the PSNR of hand-made pictures against the
// hand-computed figure, and the program on PNG files (its line, its status, its refusals).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "app/image_difference.h"
#include "app/png_reader.h"
#include "app/error.h"
#include "app/png_writer.h"
#include "support/run_program.h"

namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("image-psnr-" + std::to_string(::getpid()) + "-" + name)).string();
}

// Two opaque grey pixels; the second one's red channel is `redChange` levels brighter in the other picture.
app::Rgba8Image twoPixels(int redChange) {
    return {2, 1, {100, 100, 100, 255, static_cast<std::uint8_t>(100 + redChange), 100, 100, 255}};
}

}  // namespace

TEST(ImagePsnr, MatchesTheHandComputedFigure) {
    // One channel of six off by 10: MSE = 100 / 6, PSNR = 10 log10(255^2 x 6 / 100) = 35.912 dB.
    const app::ImageDifference d = app::compareImages(twoPixels(0), twoPixels(10));
    EXPECT_NEAR(d.meanSquaredError, 100.0 / 6.0, 1e-9);
    EXPECT_NEAR(d.psnr, 35.912, 1e-3);
    EXPECT_EQ(d.differingPixels, 1u);
    // Alpha is not part of the picture's colour.
    app::Rgba8Image translucent = twoPixels(0);
    translucent.pixels[3] = 0;
    EXPECT_TRUE(std::isinf(app::compareImages(twoPixels(0), translucent).psnr));
    EXPECT_THROW(app::compareImages(twoPixels(0), app::Rgba8Image{1, 1, {0, 0, 0, 255}}), app::Error);
}

TEST(ImagePsnr, ProgramPrintsOneLineAndRefusesBadInput) {
    const std::string a = tempPath("a.png"), b = tempPath("b.png"), small = tempPath("small.png");
    app::writePng(a, twoPixels(0));
    app::writePng(b, twoPixels(10));
    app::writePng(small, app::Rgba8Image{1, 1, {0, 0, 0, 255}});
    EXPECT_EQ(app::readPng(b).pixels, twoPixels(10).pixels) << "a PNG reads back as written";
    const test::ProgramResult same = test::runProgram(IMAGE_PSNR_BINARY, a + " " + a);
    EXPECT_EQ(same.exitCode, 0);
    EXPECT_EQ(same.out, "PSNR inf dB, MSE 0.000, 0.000 % of 2x1 pixels differ\n");
    const test::ProgramResult differ = test::runProgram(IMAGE_PSNR_BINARY, a + " " + b);
    EXPECT_EQ(differ.exitCode, 0);
    EXPECT_EQ(differ.out, "PSNR 35.91 dB, MSE 16.667, 50.000 % of 2x1 pixels differ\n");
    for (const std::string& arguments : {a + " " + small, a + " " + tempPath("missing.png"), a}) {
        const test::ProgramResult bad = test::runProgram(IMAGE_PSNR_BINARY, arguments);
        EXPECT_EQ(bad.exitCode, 1) << arguments;
        EXPECT_TRUE(bad.out.empty()) << arguments;
        EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    }
    for (const std::string& path : {a, b, small}) std::filesystem::remove(path);
}
