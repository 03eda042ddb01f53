// The largest image a crowd can be drawn into (app::largestFittingSize, crowd-view's answer to a window
// past the device's limits): a small target fits with every anti-aliasing as it is; a huge one with 4
// samples does not, and the size found keeps its shape and passes every check it failed.
#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "app/render_target.h"
#include "support/gpu_test.h"

using test::GpuTest;

namespace {

crowdgpu::RendererSettings settingsWith(VkSampleCountFlagBits samples, bool edgeFilter) {
    app::AntiAliasing antiAliasing;
    antiAliasing.samples = samples;
    antiAliasing.edgeFilter = edgeFilter;
    return app::rendererSettings(app::CullOptions{}, crowdgpu::Method::TwoPass, crowdgpu::Animation::Gpu, true, 65536,
                                 antiAliasing);
}

}  // namespace

TEST_F(GpuTest, ASmallTargetFitsAsItIsWithEveryAntiAliasing) {
    crowdgpu::GridLayout layout;
    layout.count = 4;
    const crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
    for (const VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_4_BIT})
        for (const bool edgeFilter : {false, true}) {
            const crowdgpu::RendererSettings settings = settingsWith(samples, edgeFilter);
            EXPECT_EQ(app::RenderTarget::limitProblem(*device, {640, 360}, settings.target, edgeFilter), "");
            const app::FittingSize fitting = app::largestFittingSize(*device, crowd, settings, {640, 360});
            EXPECT_EQ(fitting.size.width, 640u);
            EXPECT_EQ(fitting.size.height, 360u);
            EXPECT_EQ(fitting.why, "") << samples << " samples, edge filter " << edgeFilter;
        }
}

// 16384 x 8192 with 4 samples: 2 GiB of colour samples and as much depth, past any heap of 4 GiB or
// less and lavapipe's largest image. Where a device holds it, the test has nothing to check.
TEST_F(GpuTest, AHugeMultisampledTargetIsScaledToTheLargestThatFitsKeepingItsShape) {
    crowdgpu::GridLayout layout;
    layout.count = 4;
    const crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
    const crowdgpu::RendererSettings settings = settingsWith(VK_SAMPLE_COUNT_4_BIT, true);
    const VkExtent2D huge{16384, 8192};
    const app::FittingSize fitting = app::largestFittingSize(*device, crowd, settings, huge);
    if (fitting.why.empty()) GTEST_SKIP() << "this device draws 16384 x 8192 with 4 samples";
    EXPECT_LT(fitting.size.width, huge.width);
    EXPECT_NEAR(static_cast<double>(fitting.size.width) / fitting.size.height, 2.0, 0.01);
    EXPECT_GE(fitting.size.width, 1024u);
    EXPECT_EQ(app::RenderTarget::limitProblem(*device, fitting.size, settings.target, true), "");
    EXPECT_LE(app::estimateCrowdBytes(*device, crowd, settings, fitting.size), device->deviceLocalBytes());
    // And it is the largest: 2 % more on each side does not fit.
    const VkExtent2D more{fitting.size.width * 102 / 100, fitting.size.height * 102 / 100};
    EXPECT_FALSE(app::RenderTarget::limitProblem(*device, more, settings.target, true).empty() &&
                 app::estimateCrowdBytes(*device, crowd, settings, more) <= device->deviceLocalBytes());
    std::printf("16384x8192 with 4 samples and the edge filter: drawn at %ux%u (%s)\n", fitting.size.width,
                fitting.size.height, fitting.why.c_str());
}
