// The ground's sunlight from the ground sunlight image (render/ground_sunlight.h: the shadow map's
// comparisons made once per map texel in compute, fetched once per pixel, trilinearly) against what it
// replaces, the shadow map's comparisons at each pixel in the ground's fragment shader, both measured against a 4x4
// supersampled render of the latter: the same shadows in the same places, for a group of walking
// soldiers seen from above. Where a map texel is smaller than a pixel the image's levels average the
// shadows, which the comparisons at the pixel centre do not, so it may only be closer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/image_difference.h"
#include "app/image_downsample.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

enum class Ground { SunlightImage, PerPixelReference, Unshadowed };

struct View {
    glm::vec3 eye, target;
};
constexpr View kFromAbove{{2.0f, 9.0f, 12.0f}, {0.0f, 0.0f, 0.0f}};
// From 4 m up along -z towards the horizon, over the soldiers: the far ground samples the image's
// coarsest levels (tests/test_ground_filter.cpp looks the same way).
constexpr View kAlongTheGround{{0.0f, 4.0f, 6.0f}, {0.0f, 2.5f, -60.0f}};

app::Rgba8Image renderGroup(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, Ground ground,
                            VkExtent2D size, View view = kFromAbove) {
    std::vector<crowd::Character> characters;
    for (int row = 0; row < 5; ++row)
        for (int column = 0; column < 6; ++column) {
            crowd::Character c;
            c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
            c.position = {static_cast<float>(column) * 1.7f - 4.0f, 0.0f, static_cast<float>(row) * 1.9f - 4.0f};
            c.heading = 0.4f * static_cast<float>(row * 6 + column);
            c.timeOffset = 0.13f * static_cast<float>(column + row);
            characters.push_back(c);
        }
    crowd::Crowd crowd(soldier, characters);
    test::RendererOptions options;
    options.size = size;
    options.method = skin::Method::Compute;
    options.shadows = ground != Ground::Unshadowed;
    options.perPixelGroundShadows = ground == Ground::PerPixelReference;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera.eye = view.eye;
    renderer.camera.target = view.target;
    renderer.renderFrame(0.5);
    return renderer.readback();
}

// Pixels that shadows darkened by more than 8 of 255 in every colour channel.
std::vector<bool> darkened(const app::Rgba8Image& shadowed, const app::Rgba8Image& unshadowed) {
    return test::darkenedPixels(shadowed, unshadowed, 8);
}

// The share of pixels darkened in either picture that are darkened in both.
double overlap(const std::vector<bool>& a, const std::vector<bool>& b) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.size(); ++i) both += a[i] && b[i], either += a[i] || b[i];
    return either == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(either);
}

}  // namespace

TEST_F(GpuTest, GroundSunlightImageIsAsCloseToTheSupersampledShadowsAsComparisonsAtEachPixel) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    constexpr VkExtent2D size{320, 180};
    const app::Rgba8Image image = renderGroup(*context, soldier, Ground::SunlightImage, size);
    const app::Rgba8Image perPixel = renderGroup(*context, soldier, Ground::PerPixelReference, size);
    const app::Rgba8Image unshadowed = renderGroup(*context, soldier, Ground::Unshadowed, size);
    const app::Rgba8Image supersampled = app::boxDownsample(
        renderGroup(*context, soldier, Ground::PerPixelReference, {size.width * 4, size.height * 4}), 4);

    const std::vector<bool> shadows = darkened(supersampled, unshadowed);
    const std::size_t shadowed = static_cast<std::size_t>(std::count(shadows.begin(), shadows.end(), true));
    ASSERT_GT(shadowed, 1000u) << "thirty soldiers' shadows cover some ground";
    const double imageOverlap = overlap(darkened(image, unshadowed), shadows);
    const double perPixelOverlap = overlap(darkened(perPixel, unshadowed), shadows);
    const double imagePsnr = app::compareImages(image, supersampled).psnr;
    const double perPixelPsnr = app::compareImages(perPixel, supersampled).psnr;
    const double unshadowedPsnr = app::compareImages(unshadowed, supersampled).psnr;
    std::printf("against the 4x4 supersampled render (%zu shadowed pixels): sunlight image %.2f dB, overlap %.3f; "
                "comparisons at each pixel %.2f dB, overlap %.3f; no shadows %.2f dB\n",
                shadowed, imagePsnr, imageOverlap, perPixelPsnr, perPixelOverlap, unshadowedPsnr);
    EXPECT_GT(imageOverlap, perPixelOverlap - 0.02) << "the shadows fall where the reference's fall";
    EXPECT_GT(imagePsnr, perPixelPsnr - 0.25);
    EXPECT_GT(imagePsnr, unshadowedPsnr + 3.0) << "the shadows are much of what the pictures show";
}

// Looking along the ground, the far field (where a map texel is far under a pixel) is as bright as the
// supersampled render of the comparisons made at each pixel: the image's coarse levels are the means of
// its fine ones, made this frame, whatever the viewport's size picked as the first level.
TEST_F(GpuTest, GroundSunlightFarFieldKeepsTheSupersampledBrightness) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    constexpr VkExtent2D size{256, 144};
    const app::Rgba8Image image = renderGroup(*context, soldier, Ground::SunlightImage, size, kAlongTheGround);
    const app::Rgba8Image supersampled = app::boxDownsample(
        renderGroup(*context, soldier, Ground::PerPixelReference, {size.width * 4, size.height * 4}, kAlongTheGround), 4);
    // The mean of a row over its colour channels, 8-bit levels.
    const auto rowMean = [&](const app::Rgba8Image& picture, std::uint32_t y) {
        double sum = 0.0;
        for (std::uint32_t x = 0; x < size.width; ++x)
            for (int ch = 0; ch < 3; ++ch) sum += picture.pixels[(static_cast<std::size_t>(y) * size.width + x) * 4 + ch];
        return sum / (3.0 * size.width);
    };
    // The forty rows below the horizon (the first row that is not the sky's colour, and the next, which
    // mixes sky and ground in the supersampled render): the ground from about 400 m to 30 m.
    std::uint32_t horizon = 0;
    while (horizon < size.height && std::abs(rowMean(image, horizon) - rowMean(image, 0)) < 0.5) ++horizon;
    ASSERT_LT(horizon + 42, size.height) << "the view sees ground below its horizon";
    double worst = 0.0;
    for (std::uint32_t y = horizon + 1; y < horizon + 41; ++y)
        worst = std::max(worst, std::abs(rowMean(image, y) - rowMean(supersampled, y)));
    std::printf("far rows: largest difference of a row's mean from the supersampled render's %.2f levels\n", worst);
    EXPECT_LT(worst, 1.5);  // measured 0.78; reading levels never made this frame: 2.92
}
