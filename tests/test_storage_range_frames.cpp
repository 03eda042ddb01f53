// Frames whose settings or viewport make a compute pass's buffer larger than one storage binding may be
// (maxStorageBufferRange: 128 MiB on lavapipe, the least Vulkan allows). Each such pass binds its buffer
// whole, so it must not run there: the shadow map's casters go to the hardware pass, and under raster
// auto the impostors and small meshes go to the hardware rasterizer and the far crowd is left out, each
// drawing the picture that path draws; raster compute, asked for such a viewport, refuses it in one line.
// Validation (with synchronization validation) stays silent: binding past the range is a validation
// error, which fails the test. On a device whose range holds these buffers the tests skip.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "frame/memory_plan.h"
#include "render/far_crowd_layer.h"
#include "render/shadow_raster.h"
#include "render/visibility_resolve.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

gpu::ImpostorSplit impostorSplitOf(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    return test::readAll<gpu::ImpostorSplit>(context, renderer.recorder().impostorRaster()->split()).at(0);
}

// Impostors on, single-sampled, no shadows, one frame in flight, at these LOD and impostor thresholds.
test::RendererOptions impostorOptions(VkExtent2D size, float lod0, float lod1, float impostor) {
    test::RendererOptions options;
    options.size = size;
    options.method = skin::Method::Compute;
    options.shadows = false;
    options.framesInFlight = 1;
    options.cull.impostors = true;
    options.cull.lodThresholds[0] = lod0;
    options.cull.lodThresholds[1] = lod1;
    options.cull.impostorThreshold = impostor;
    return options;
}

app::Rgba8Image pictureOf(test::TestRenderer& renderer, const app::Camera& camera, double time) {
    renderer.camera = camera;
    renderer.renderFrame(time);
    renderer.finish();
    renderer.takeStats();
    return renderer.readback();
}

bool hasItem(const std::vector<skin::MemoryItem>& items, const std::string& name) {
    for (const skin::MemoryItem& item : items)
        if (item.what == name) return true;
    return false;
}

// A crowd seen from `factor` times its framed distance (the Framed path looks down on it).
app::Camera pulledBack(const app::CrowdShape& shape, float factor) {
    app::Camera camera = app::cameraOnPath(app::CameraPath::Framed, shape, 1.0f, 0.0);
    camera.eye = camera.target + factor * (camera.eye - camera.target);
    camera.farPlane = std::max(camera.farPlane, 4.0f * glm::length(camera.eye - camera.target));
    return camera;
}

}  // namespace

// The boundaries, from the formats' bytes: 4-byte depths a texel (5792² is the largest square map in
// 128 MiB), an 8-byte word a pixel for a visibility buffer (4096 x 4096), 32 bytes a pixel for the far
// layer's sums (2048 x 2048).
TEST(StorageRangeFrames, TheLimitsFollowTheBuffersBytes) {
    VkPhysicalDeviceLimits limits{};
    limits.maxStorageBufferRange = 128u << 20;
    EXPECT_TRUE(render::ShadowRaster::fits(limits, 5792));
    EXPECT_FALSE(render::ShadowRaster::fits(limits, 5793));
    EXPECT_TRUE(render::visibilityFits(limits, {4096, 4096}));
    EXPECT_FALSE(render::visibilityFits(limits, {4097, 4096}));
    EXPECT_TRUE(render::FarCrowdLayer::fits(limits, {2048, 2048}));
    EXPECT_FALSE(render::FarCrowdLayer::fits(limits, {2048, 2049}));
    limits.maxStorageBufferRange = 0xFFFFFFFFu;  // the H100's: every map up to the 16384 allowed
    EXPECT_TRUE(render::ShadowRaster::fits(limits, 16384));
}

// A 6000² map (137 MiB of float depths): the compute pass is not made, its bytes are not planned, and the
// hardware pass draws the map. The picture has its shadows (darker than with shadows off on over 100
// pixels) and equals, in every channel of every pixel, that of a renderer asked for the hardware pass.
TEST_F(GpuTest, AShadowMapPastTheStorageRangeIsDrawnByTheHardwarePass) {
    constexpr std::uint32_t kMapSize = 6000;
    const std::uint64_t range = context->properties.limits.maxStorageBufferRange;
    if (std::uint64_t{kMapSize} * kMapSize * 4 <= range)  // its float depths
        GTEST_SKIP() << "this device binds a " << kMapSize << "² map's depths as one storage buffer";
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 20;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.shadowMapSize = kMapSize;
    options.framesInFlight = 1;
    ASSERT_EQ(options.shadowRaster, render::ShadowRasterPath::Compute);  // the default, asked for
    EXPECT_FALSE(hasItem(frame::planMemory(*context, crowd, options).items, "shadow map depth (compute raster)"));
    test::TestRenderer asked(*device, crowd, options);
    EXPECT_EQ(asked.recorder().computeShadowRaster(), nullptr);
    EXPECT_FALSE(hasItem(asked.recorder().memory(), "shadow map depth (compute raster)"));
    const app::CrowdShape shape = test::shapeOf(crowd);
    const app::Camera camera = pulledBack(shape, 1.0f);
    const app::Rgba8Image picture = pictureOf(asked, camera, 0.7);
    EXPECT_FALSE(asked.recorder().rastersShadowsInCompute());

    options.shadowRaster = render::ShadowRasterPath::Hardware;
    test::TestRenderer hardware(*device, crowd, options);
    const app::Rgba8Image hardwarePicture = pictureOf(hardware, camera, 0.7);
    options.shadows = false;
    test::TestRenderer unshadowed(*device, crowd, options);
    const app::Rgba8Image unshadowedPicture = pictureOf(unshadowed, camera, 0.7);
    std::size_t darkened = 0;
    for (const bool d : test::darkenedPixels(picture, unshadowedPicture, 8)) darkened += d ? 1 : 0;
    std::printf("%u² map: %zu pixels in shadow\n", kMapSize, darkened);
    EXPECT_GT(darkened, 100u) << "the map holds the casters";
    EXPECT_EQ(test::fractionOfMatchingPixels(picture, hardwarePicture, 0), 1.0);
}

// A 16384 x 1025 viewport (a visibility buffer of 128.1 MiB; the height of a 1024 x 1024 one, so the
// same sizes on screen) under raster auto, with a mesh limit that sends every mesh to compute where it
// can, the soldiers seen low across the crowd: the nearer are meshes, the farther impostors under the 128
// px that auto rasterizes in compute. Here none is rasterized in compute (the impostors all go to the
// hardware list, no mesh to the mesh path), and the picture equals raster hardware's in every channel of
// every pixel. The same renderer at 1024 x 1024 rasterizes both in compute again (its one-pixel stand-in
// buffer made again at the viewport). Raster compute at 16384 x 1025 refuses the frame in one line naming
// the range.
TEST_F(GpuTest, AViewportPastTheStorageRangeDrawsOnTheHardwareUnderAuto) {
    constexpr VkExtent2D kLarge{16384, 1025};
    const std::uint64_t range = context->properties.limits.maxStorageBufferRange;
    if (std::uint64_t{kLarge.width} * kLarge.height * 8 <= range)  // a 64-bit word a pixel
        GTEST_SKIP() << "this device binds a 16384 x 1025 visibility buffer as one storage buffer";
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 200;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    // The farther soldiers impostors (under the 128 px auto rasterizes in compute), the nearer meshes.
    test::RendererOptions options = impostorOptions(kLarge, 1000.0f, 600.0f, 60.0f);
    options.cull.lodFade = false;
    options.raster = render::RasterMode::Auto;
    options.meshRasterLimitPixels = 100000.0f;
    test::TestRenderer automatic(*device, crowd, options);
    options.atlas = automatic.impostorAtlas();
    const app::CrowdShape shape = test::shapeOf(crowd);
    app::Camera camera = app::cameraOnPath(app::CameraPath::Framed, shape, 1.0f, 0.0);
    camera.target = shape.center + glm::vec3(0.0f, 1.0f, 0.0f);
    camera.eye = shape.center + glm::vec3(0.0f, 2.0f, shape.radius + 40.0f);
    const app::Rgba8Image picture = pictureOf(automatic, camera, 0.5);
    const gpu::ImpostorSplit split = impostorSplitOf(*context, automatic);
    const std::uint32_t meshes = automatic.drawLists().countsOf(0).visible();
    std::printf("16384 x 1025: %u impostors to the hardware, %u in compute; %u meshes, %s\n", split.hardwareCount,
                split.computeCount, meshes,
                automatic.recorder().meshesInComputeThisFrame(0) ? "in compute" : "on the hardware");
    EXPECT_GT(split.hardwareCount, 5u);
    EXPECT_EQ(split.computeCount, 0u);
    EXPECT_GT(meshes, 5u);
    EXPECT_FALSE(automatic.recorder().meshesInComputeThisFrame(0));

    options.raster = render::RasterMode::Hardware;
    test::TestRenderer hardware(*device, crowd, options);
    EXPECT_EQ(test::fractionOfMatchingPixels(picture, pictureOf(hardware, camera, 0.5), 0), 1.0);

    automatic.resize({1024, 1024});
    pictureOf(automatic, camera, 0.5);
    const gpu::ImpostorSplit small = impostorSplitOf(*context, automatic);
    ASSERT_TRUE(automatic.recorder().meshesInComputeThisFrame(0));
    const gpu::MeshSplit meshSplit =
        test::readAll<gpu::MeshSplit>(*context, automatic.recorder().meshRaster()->split()).at(0);
    std::printf("1024 x 1024: %u impostors in compute, %u meshes in compute\n", small.computeCount,
                meshSplit.computeCount);
    EXPECT_GT(small.computeCount, 5u);
    EXPECT_GT(meshSplit.computeCount, 5u);

    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, crowd, options);
    try {
        pictureOf(compute, camera, 0.5);
        ADD_FAILURE() << "raster compute drew a viewport past the storage range";
    } catch (const std::exception& e) {
        const std::string message = e.what();
        std::printf("raster compute at 16384 x 1025: %s\n", message.c_str());
        EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
        EXPECT_NE(message.find("16384x1025"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// A 2100 x 2100 viewport: its visibility buffer fits, the far layer's sums (141 MiB) do not. With
// far-crowd on, no impostor is averaged and the picture equals far-crowd off's in every channel of every
// pixel; at 1400 x 1400 (the layer fits) the same renderer averages the far crowd again.
TEST_F(GpuTest, AFarLayerPastTheStorageRangeIsLeftOut) {
    constexpr VkExtent2D kLarge{2100, 2100};
    const std::uint64_t range = context->properties.limits.maxStorageBufferRange;
    if (std::uint64_t{kLarge.width} * kLarge.height * 32 <= range)  // eight 32-bit sums a pixel
        GTEST_SKIP() << "this device binds a 2100 x 2100 far layer as one storage buffer";
    ASSERT_LE(std::uint64_t{kLarge.width} * kLarge.height * 8, range);
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 300;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options = impostorOptions(kLarge, 4000.0f, 3000.0f, 2000.0f);  // every soldier an impostor
    options.raster = render::RasterMode::Compute;
    options.farCrowd = true;
    test::TestRenderer averaging(*device, crowd, options);
    options.atlas = averaging.impostorAtlas();
    const app::Camera camera = pulledBack(test::shapeOf(crowd), 20.0f);
    const app::Rgba8Image picture = pictureOf(averaging, camera, 0.5);
    const gpu::ImpostorSplit split = impostorSplitOf(*context, averaging);
    EXPECT_GT(split.computeCount, 100u);
    EXPECT_EQ(split.averagedCount, 0u);
    EXPECT_EQ(averaging.recorder().impostorRaster()->farLayer(), nullptr);

    options.farCrowd = false;
    test::TestRenderer plain(*device, crowd, options);
    EXPECT_EQ(test::fractionOfMatchingPixels(picture, pictureOf(plain, camera, 0.5), 0), 1.0);

    averaging.resize({1400, 1400});
    pictureOf(averaging, camera, 0.5);
    const gpu::ImpostorSplit small = impostorSplitOf(*context, averaging);
    std::printf("2100 x 2100: %u impostors in compute, none averaged; 1400 x 1400: %u averaged\n",
                split.computeCount, small.averagedCount);
    EXPECT_GT(small.averagedCount, 100u);
}
