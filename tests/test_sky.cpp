// The sky instead of a colour clear (crowdgpu::RendererSettings::sky, docs/gpu-driven-frame.md): with
// the sky on, the programs' target begins its pass without clearing its colour (loadOp DONT_CARE),
// and recordCharacters colours every pixel nothing else drew. The picture must be the cleared one,
// pixel for pixel (alpha too), whatever the frame before left in the target.
#include <cstdio>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr VkExtent2D kSize{160, 90};

// A crowd seen first from straight above (no sky: the frame fills the target with ground and
// soldiers), then from inside it looking along the ground (about 40 % sky), and once more from above.
// With the colour not cleared, a pixel of the sky the sky pass missed keeps what the frame before left
// there, so each picture must equal the cleared renderer's.
// `atlas`: the impostor atlas baked by the first renderer, shared by the others (baking is most of the
// test's time on lavapipe).
std::vector<app::Rgba8Image> renderViews(const gpu::VulkanContext& context, const model::SkinnedModel& soldier,
                                         bool sky, VkSampleCountFlagBits samples,
                                         std::shared_ptr<const render::ImpostorAtlas>& atlas) {
    app::SceneOptions scene;
    scene.count = 300;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = kSize;
    options.method = skin::Method::Compute;
    options.cull.impostors = true;
    // Multisampled, the impostors on the hardware: their sample masks must leave every sample's alpha
    // written (alpha to coverage did not: with no clear it was undefined).
    options.raster = samples == VK_SAMPLE_COUNT_1_BIT ? render::RasterMode::Auto : render::RasterMode::Hardware;
    options.target.samples = samples;
    options.framesInFlight = 1;
    options.sky = sky;
    options.atlas = atlas;
    test::TestRenderer renderer(context, crowd, options);
    atlas = renderer.impostorAtlas();
    const app::CrowdShape shape = test::shapeOf(crowd);
    std::vector<app::Rgba8Image> pictures;
    for (int view = 0; view < 3; ++view) {
        app::Camera camera;
        if (view == 1) {
            camera.eye = shape.center + glm::vec3(0.0f, 1.7f, 0.0f);
            camera.target = shape.center + glm::vec3(0.0f, 2.5f, 40.0f);
        } else {
            camera.eye = shape.center + glm::vec3(0.0f, 30.0f, 0.1f);
            camera.target = shape.center;
        }
        renderer.camera = camera;
        renderer.renderFrame(1.0 + 0.5 * view);
        renderer.finish();
        pictures.push_back(renderer.readback());
    }
    return pictures;
}

// The share of a picture's pixels in the sky's colour: the top-left pixel of `skyFrom`, a view whose
// top row is sky.
double skyShare(const app::Rgba8Image& image, const app::Rgba8Image& skyFrom) {
    std::size_t sky = 0;
    const std::size_t pixels = std::size_t{image.width} * image.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        bool same = true;
        for (std::size_t c = 0; c < 3; ++c) same = same && image.pixels[i * 4 + c] == skyFrom.pixels[c];
        sky += same ? 1 : 0;
    }
    return double(sky) / double(pixels);
}

}  // namespace

TEST_F(GpuTest, TheSkyWritesEveryPixelAColourClearWould) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const VkSampleCountFlags counts =
        device->properties.limits.framebufferColorSampleCounts & device->properties.limits.framebufferDepthSampleCounts;
    std::vector<VkSampleCountFlagBits> sampleCounts{VK_SAMPLE_COUNT_1_BIT};
    if (counts & VK_SAMPLE_COUNT_4_BIT) sampleCounts.push_back(VK_SAMPLE_COUNT_4_BIT);
    std::shared_ptr<const render::ImpostorAtlas> atlas;
    for (const VkSampleCountFlagBits samples : sampleCounts) {
        const std::vector<app::Rgba8Image> cleared = renderViews(*context, soldier, false, samples, atlas);
        const std::vector<app::Rgba8Image> drawn = renderViews(*context, soldier, true, samples, atlas);
        const double skyAbove = skyShare(cleared[0], cleared[1]), skyAlong = skyShare(cleared[1], cleared[1]);
        std::printf("%u sample(s): sky %.1f %% of the view from above, %.1f %% of the view along the ground\n",
                    unsigned(samples), 100.0 * skyAbove, 100.0 * skyAlong);
        EXPECT_LT(skyAbove, 0.01) << "the first view must fill the target";
        EXPECT_GT(skyAlong, 0.2) << "the second view must show sky";
        for (std::size_t view = 0; view < cleared.size(); ++view) {
            const double matching = test::fractionOfMatchingPixels(cleared[view], drawn[view], 0);
            std::printf("  view %zu: %.3f %% of pixels equal to the cleared picture's\n", view, 100.0 * matching);
            EXPECT_EQ(matching, 1.0) << unsigned(samples) << " sample(s), view " << view;
        }
    }
}
