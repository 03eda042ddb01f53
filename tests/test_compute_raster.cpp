// The compute rasterizer of impostors (docs/compute-raster.md): its picture against the hardware
// path's for a mixed crowd, the depth merge where meshes and impostors overlap (both ways), the
// visibility buffer's ids against a CPU projection of hand-placed characters, an impostor crossing
// auto's size limit between frames, and the refusals.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "app/crowd_renderer.h"
#include "app/image_difference.h"
#include "render/frame_view.h"
#include "support/gpu_test.h"
#include "support/run_program.h"

namespace {

using test::GpuTest;

constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

// One frame of a renderer: its picture and, with the compute rasterizer, what it left behind.
struct RasterFrame {
    app::Rgba8Image image;
    render::LodCounts lods;
    std::vector<std::uint64_t> visibility;  // empty on the hardware path
    std::vector<std::uint32_t> impostorList;
    gpu::ImpostorSplit split{};
};

// Renders one frame at `time` (renderers here have one frame in flight, so slot 0).
RasterFrame renderFrame(const gpu::VulkanContext& context, test::TestRenderer& renderer, double time) {
    renderer.renderFrame(time);
    renderer.finish();
    RasterFrame frame;
    frame.lods = test::internalCounts(renderer.takeStats().back().lods);
    frame.image = renderer.readback();
    if (const render::ImpostorRaster* raster = renderer.recorder().impostorRaster()) {
        const std::vector<std::byte> words = test::readBuffer(context, raster->visibility(0));
        frame.visibility.resize(words.size() / 8);
        std::memcpy(frame.visibility.data(), words.data(), words.size());
        const std::vector<std::byte> split = test::readBuffer(context, raster->split());
        std::memcpy(&frame.split, split.data(), sizeof frame.split);
        const std::vector<std::byte> list = test::readBuffer(context, renderer.drawLists().impostorList());
        frame.impostorList.resize(list.size() / 4);
        std::memcpy(frame.impostorList.data(), list.data(), list.size());
    }
    return frame;
}

test::RendererOptions rasterOptions(VkExtent2D size, render::RasterMode raster) {
    test::RendererOptions options;
    options.size = size;
    options.method = skin::Method::Compute;
    options.cull.impostors = true;
    options.cull.hysteresis = 0.0f;
    options.framesInFlight = 1;
    options.raster = raster;
    // Every impostor cut at half coverage into the visibility buffer, the path these tests compare with
    // the hardware's pixel for pixel and id for id; the far crowd averaged (small impostors into a
    // blended layer instead) is tested in test_far_crowd.cpp.
    options.farCrowd = false;
    return options;
}

}  // namespace

// The mixed scene's crowd (soldiers and horses, 3:1; its fly-over camera) with impostors on, at every level,
// drawn by the hardware path and by the compute rasterizer: every impostor goes to compute, and the two
// pictures agree on 99.5 % of all pixels within 2/255, and over the pixels the compute path covered on
// 95 % within 2/255 and 99 % within 24/255 (lavapipe: 100 % of them within 2/255). They may differ where an atlas texel's blended coverage sits near the half cut: the
// hardware path takes its mip level from derivatives over 2x2 pixel quads, the compute path from the
// quad's own forward differences, so a few edge pixels fall on the other side of the cut.
TEST_F(GpuTest, ComputeRasterDrawsTheHardwarePictureOfAMixedCrowd) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    crowd::Crowd crowd = test::mixedCrowd(soldier, horse, 1200);
    test::RendererOptions options = rasterOptions({480, 270}, render::RasterMode::Hardware);
    test::TestRenderer hardware(*device, crowd, options);
    options.atlas = hardware.impostorAtlas();
    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, crowd, options);
    EXPECT_EQ(hardware.recorder().impostorRaster(), nullptr);
    ASSERT_NE(compute.recorder().impostorRaster(), nullptr);
    for (test::TestRenderer* r : {&hardware, &compute})
        r->camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 480.0f / 270.0f, 3.0);
    const RasterFrame h = renderFrame(*context, hardware, 11.0);
    const RasterFrame c = renderFrame(*context, compute, 11.0);
    EXPECT_GT(c.lods.characters[0] + c.lods.characters[1] + c.lods.characters[2], 20u);
    EXPECT_GT(c.lods.impostors, 50u);
    EXPECT_EQ(c.split.computeCount, c.lods.impostors);
    EXPECT_EQ(c.split.hardwareCount, 0u);
    std::size_t covered = 0, coveredClose = 0, coveredNear = 0, matching = 0;
    for (std::size_t i = 0; i < c.visibility.size(); ++i) {
        matching += test::pixelWithin(h.image, c.image, i, 2) ? 1 : 0;
        if (c.visibility[i] == kEmpty) continue;
        ++covered;
        coveredClose += test::pixelWithin(h.image, c.image, i, 2) ? 1 : 0;
        coveredNear += test::pixelWithin(h.image, c.image, i, 24) ? 1 : 0;
    }
    const double all = double(matching) / double(c.visibility.size());
    const double close = double(coveredClose) / double(std::max<std::size_t>(covered, 1));
    const double near = double(coveredNear) / double(std::max<std::size_t>(covered, 1));
    std::printf("%u impostors cover %zu pixels; within 2/255: %.2f %% of all pixels, %.2f %% of the covered ones; "
                "within 24/255: %.2f %% of the covered ones\n", c.lods.impostors, covered, 100.0 * all, 100.0 * close,
                100.0 * near);
    EXPECT_GT(covered, 1000u);
    EXPECT_GE(all, 0.995);
    EXPECT_GE(close, 0.95);
    EXPECT_GE(near, 0.99);
    if (HasFailure() || std::getenv("CROWD_KEEP_IMAGES")) test::keepRasterImages("raster-mixed", h.image, c.image);
}

namespace {

// Three soldiers on the camera's axis, shadows off: N a mesh in the middle; F an impostor behind it,
// half hidden; S a small soldier (scale 0.22) in front of N, an impostor over it.
struct OverlapScene {
    std::vector<crowd::Character> characters;
    render::Camera camera;
};

OverlapScene overlapScene(const model::SkinnedModel& soldier) {
    OverlapScene scene;
    crowd::Character n, f, s;
    n.position = glm::vec3(0.0f);
    f.position = glm::vec3(0.35f, 0.0f, -7.0f);
    s.position = glm::vec3(-0.08f, 0.8f, 3.0f);
    s.scale = 0.22f;
    f.heading = 0.6f;
    s.heading = 2.0f;
    f.timeOffset = 0.3f;
    scene.characters = {n, f, s};
    const float centre = glm::vec3(soldier.poseSphere).y;
    scene.camera.eye = glm::vec3(0.0f, centre + 0.4f, 6.0f);
    scene.camera.target = glm::vec3(0.0f, centre, 0.0f);
    scene.camera.nearPlane = 0.2f;
    scene.camera.farPlane = 60.0f;
    return scene;
}

}  // namespace

// The depth merge: the resolve writes the rasterizer's depth, so where a mesh stands in front of a
// compute-drawn impostor the mesh shows, and where a compute-drawn impostor stands in front of a mesh the
// impostor shows, as on the hardware path. Over the pixels where the mesh and an impostor overlap (the
// impostor's id in the visibility buffer, the mesh's in its own picture), the compute path's picture
// equals the hardware's within 2/255 on 95 % of them, for each of the two orders.
TEST_F(GpuTest, ComputeRasterMergesWithMeshesByDepth) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const OverlapScene scene = overlapScene(soldier);
    crowd::Crowd all(soldier, scene.characters);
    // The same crowd with characters shrunk to nothing: its shape (centre, radius), and so the ground, fog
    // and shadow fit, stay the same, so the pictures differ only where the remaining characters stand.
    auto shrunk = [&](std::initializer_list<int> gone) {
        std::vector<crowd::Character> characters = scene.characters;
        for (const int i : gone) characters[i].scale = 1e-3f;
        return characters;
    };
    crowd::Crowd meshOnly(soldier, shrunk({1, 2}));
    crowd::Crowd empty(soldier, shrunk({0, 1, 2}));
    test::RendererOptions options = rasterOptions({240, 180}, render::RasterMode::Hardware);
    options.shadows = false;  // so a character changes only the pixels it covers
    options.cull.impostorThreshold = 45.0f;
    test::TestRenderer hardware(*device, all, options);
    options.atlas = hardware.impostorAtlas();
    test::TestRenderer meshRenderer(*device, meshOnly, options);
    test::TestRenderer emptyRenderer(*device, empty, options);
    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, all, options);
    for (test::TestRenderer* r : {&hardware, &meshRenderer, &emptyRenderer, &compute}) r->camera = test::appCamera(scene.camera);
    const RasterFrame h = renderFrame(*context, hardware, 0.5);
    const RasterFrame c = renderFrame(*context, compute, 0.5);
    const RasterFrame mesh = renderFrame(*context, meshRenderer, 0.5);
    const RasterFrame background = renderFrame(*context, emptyRenderer, 0.5);
    ASSERT_EQ(c.lods.impostors, 2u);
    ASSERT_EQ(c.lods.characters[0] + c.lods.characters[1] + c.lods.characters[2], 1u);
    EXPECT_EQ(c.split.computeCount, 2u);
    std::size_t meshPixels = 0;
    for (std::size_t i = 0; i < c.visibility.size(); ++i) meshPixels += test::pixelWithin(mesh.image, background.image, i, 0) ? 0 : 1;
    EXPECT_LT(meshPixels, c.visibility.size() / 4);  // the mesh's own pixels, not the whole picture
    std::map<std::uint32_t, std::size_t> overlap, matching, covered;  // by character: 1 behind, 2 in front
    for (std::size_t i = 0; i < c.visibility.size(); ++i) {
        if (c.visibility[i] == kEmpty) continue;
        const std::uint32_t character = c.impostorList[c.visibility[i] & 0xFFFFFFFFu];
        ++covered[character];
        if (test::pixelWithin(mesh.image, background.image, i, 0)) continue;  // the mesh does not cover it
        ++overlap[character];
        matching[character] += test::pixelWithin(h.image, c.image, i, 2) ? 1 : 0;
    }
    for (const std::uint32_t character : {1u, 2u}) {
        const double fraction = double(matching[character]) / double(std::max<std::size_t>(overlap[character], 1));
        std::printf("impostor %u (%s the mesh): %zu pixels, %zu over the mesh, %.1f %% of those as on the hardware path\n",
                    character, character == 1 ? "behind" : "in front of", covered[character], overlap[character],
                    100.0 * fraction);
        EXPECT_GE(overlap[character], 25u) << "character " << character;
        EXPECT_LT(overlap[character], covered[character]) << "character " << character << " is wholly overlapped";
        EXPECT_GE(fraction, 0.95) << "character " << character;
    }
    // Not trivially so: the mesh and each impostor differ over the overlap.
    std::size_t meshDiffers = 0;
    for (std::size_t i = 0; i < c.visibility.size(); ++i)
        if (c.visibility[i] != kEmpty && !test::pixelWithin(mesh.image, background.image, i, 0) && !test::pixelWithin(h.image, mesh.image, i, 2))
            ++meshDiffers;
    EXPECT_GE(meshDiffers, 30u);
    if (HasFailure() || std::getenv("CROWD_KEEP_IMAGES")) test::keepRasterImages("raster-overlap", h.image, c.image);
}

// The visibility buffer's ids: seven soldiers far apart, all impostors, rasterized in compute (five
// large enough for the second dispatch, two far ones drawn by one thread each). Every
// covered pixel's id names, through the impostor list, the soldier whose pose sphere's projection (CPU,
// from the camera's matrices) holds the pixel, and its depth lies within that sphere's depth range;
// every soldier covers pixels. (Impostors have no triangles: a quad's pixels are those whose centre
// lies on it and whose atlas coverage reaches a half, and its edges are empty atlas texels, so no
// top-left rule is at stake; mesh triangles stay on the hardware path.)
TEST_F(GpuTest, VisibilityIdsDecodeToTheCharacterUnderThePixel) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    // Five near ones (over IMPOSTOR_RASTER_LARGE_PIXELS: a workgroup each) and two far ones (a thread each).
    std::vector<crowd::Character> five;
    for (int i = 0; i < 7; ++i) {
        crowd::Character c;
        c.position = i < 5 ? glm::vec3(3.0f * float(i - 2), 0.0f, -4.0f * float(i % 2))
                           : glm::vec3(i == 5 ? -5.0f : 5.0f, 0.0f, -26.0f);
        c.clip = static_cast<std::uint32_t>(i % soldier.clips.size());
        c.timeOffset = 0.2f * float(i);
        five.push_back(c);
    }
    crowd::Crowd crowd(soldier, five);
    test::RendererOptions options = rasterOptions({320, 120}, render::RasterMode::Compute);
    test::TestRenderer renderer(*device, crowd, options);
    render::Camera camera;
    const float centre = glm::vec3(soldier.poseSphere).y;
    camera.eye = glm::vec3(0.0f, centre + 2.0f, 14.0f);
    camera.target = glm::vec3(0.0f, centre, -2.0f);
    camera.nearPlane = 0.5f;
    camera.farPlane = 100.0f;
    renderer.camera = test::appCamera(camera);
    const RasterFrame frame = renderFrame(*context, renderer, 0.7);
    ASSERT_EQ(frame.lods.impostors, 7u);
    EXPECT_EQ(frame.split.computeCount, 7u);
    EXPECT_EQ(frame.split.largeCount, 5u);
    const render::FrameView view = render::frameViewOf(camera, {320, 120}, 0.7);
    const glm::mat4 viewProjection = view.projection * view.view;
    struct Projected {
        glm::vec2 pixel;
        float radius;  // pixels
        float nearDepth, farDepth;
    };
    std::vector<Projected> spheres;
    const float r = soldier.poseSphere.w;
    for (const crowd::Character& c : five) {
        const glm::vec3 world = c.position + glm::vec3(soldier.poseSphere);
        const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        const float distance = glm::length(world - camera.eye);
        const float focal = 60.0f / std::tan(0.5f * camera.verticalFov);
        const glm::vec3 towards = glm::normalize(camera.eye - world);
        auto depthAt = [&](glm::vec3 p) { const glm::vec4 q = viewProjection * glm::vec4(p, 1.0f); return q.z / q.w; };
        spheres.push_back({(ndc * 0.5f + 0.5f) * glm::vec2(320.0f, 120.0f), r * focal / distance * 1.05f + 1.0f,
                           depthAt(world + r * towards), depthAt(world - r * towards)});
    }
    std::vector<std::size_t> pixels(7, 0);
    std::size_t wrong = 0, outOfDepth = 0;
    for (std::uint32_t y = 0; y < 120; ++y)
        for (std::uint32_t x = 0; x < 320; ++x) {
            const std::uint64_t word = frame.visibility[y * 320 + x];
            if (word == kEmpty) continue;
            const std::uint32_t index = static_cast<std::uint32_t>(word & 0xFFFFFFFFu);
            ASSERT_LT(index, 7u);
            const std::uint32_t character = frame.impostorList[index];
            ASSERT_LT(character, 7u);
            ++pixels[character];
            const Projected& s = spheres[character];
            if (glm::length(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - s.pixel) > s.radius) ++wrong;
            float depth;
            const std::uint32_t bits = static_cast<std::uint32_t>(word >> 32);
            std::memcpy(&depth, &bits, 4);
            if (depth < s.nearDepth || depth > s.farDepth) ++outOfDepth;
        }
    for (int c = 0; c < 7; ++c) {
        std::printf("soldier %d: %zu pixels, %.1f px across\n", c, pixels[c], 2.0 * spheres[c].radius);
        EXPECT_GE(pixels[c], c < 5 ? 40u : 4u) << "soldier " << c;
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_EQ(outOfDepth, 0u);
}

// Auto: an impostor whose screen rectangle grows past the compute path's limit between frames moves
// to the hardware path (the split's counts say which path drew it), and its pixels do not change
// beyond the two paths' tolerance: in every frame of a camera moving in, the auto picture equals the
// hardware-only picture of the same frame within 2/255 on 97 % of the soldier's pixels and within
// 24/255 on 99 %.
TEST_F(GpuTest, AnImpostorCrossingAutosLimitKeepsItsPixels) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Character one;
    one.heading = 0.4f;
    crowd::Crowd crowd(soldier, {one});
    crowd::Character gone = one;
    gone.scale = 1e-3f;  // the same crowd's shape (ground, fog), nothing drawn
    crowd::Crowd empty(soldier, {gone});
    test::RendererOptions options = rasterOptions({160, 120}, render::RasterMode::Hardware);
    options.cull.impostorThreshold = 48.0f;
    options.shadows = false;
    test::TestRenderer hardware(*device, crowd, options);
    options.atlas = hardware.impostorAtlas();
    test::TestRenderer emptyRenderer(*device, empty, options);
    options.raster = render::RasterMode::Auto;
    options.rasterLimitPixels = 40.0f;
    test::TestRenderer automatic(*device, crowd, options);
    std::uint32_t onHardware = 0, onCompute = 0;
    for (int step = 0; step < 8; ++step) {
        // The pose sphere from 32 to 46 px across: its quad's rectangle crosses 40 px on the way.
        const float across = 32.0f + 2.0f * float(step);
        const render::Camera camera = test::cameraSeeingSphereAcross(soldier, across);
        for (test::TestRenderer* r : {&hardware, &automatic, &emptyRenderer}) r->camera = test::appCamera(camera);
        const RasterFrame h = renderFrame(*context, hardware, 0.25 * step);
        const RasterFrame a = renderFrame(*context, automatic, 0.25 * step);
        const RasterFrame e = renderFrame(*context, emptyRenderer, 0.25 * step);
        ASSERT_EQ(a.lods.impostors, 1u) << "step " << step;
        ASSERT_EQ(a.split.computeCount + a.split.hardwareCount, 1u);
        onCompute += a.split.computeCount, onHardware += a.split.hardwareCount;
        const test::CharacterAgreement agreement = test::characterAgreement(h.image, a.image, e.image);
        std::printf("%.0f px: %s path, %zu soldier pixels, %.1f %% within 2/255, %.1f %% within 24/255\n", across,
                    a.split.computeCount ? "compute" : "hardware", agreement.pixels, 100.0 * agreement.share2(),
                    100.0 * agreement.share24());
        EXPECT_GT(agreement.pixels, 100u);
        EXPECT_GE(agreement.share2(), 0.97) << "step " << step;
        EXPECT_GE(agreement.share24(), 0.99) << "step " << step;
        if (HasFailure()) test::keepRasterImages("raster-switch", h.image, a.image);
    }
    EXPECT_GE(onCompute, 2u);
    EXPECT_GE(onHardware, 2u);
}

// Two frames in flight and a target that changes size (a viewer's window): each frame slot's visibility
// buffer follows the viewport, and the picture after the resize is the hardware path's at the new size
// (99.5 % of pixels within 2/255), with validation and synchronization validation silent.
TEST_F(GpuTest, ComputeRasterFollowsATargetThatChangesSize) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 300;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options = rasterOptions({160, 90}, render::RasterMode::Hardware);
    options.framesInFlight = 2;
    options.cull.impostorThreshold = 20.0f;
    test::TestRenderer hardware(*device, crowd, options);
    options.atlas = hardware.impostorAtlas();
    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    auto frameAt = [&](test::TestRenderer& r, VkExtent2D size, int frames) {
        if (r.extent().width != size.width || r.extent().height != size.height) r.resize(size);
        const float aspect = float(size.width) / float(size.height);
        for (int i = 0; i < frames; ++i) {
            r.camera = app::cameraOnPath(app::CameraPath::Framed, shape, aspect, 0.0);
            r.renderFrame(2.0 + 0.1 * i);
        }
        r.finish();
        const render::LodCounts lods = test::internalCounts(r.takeStats().back().lods);
        EXPECT_GT(lods.impostors, 50u);
        return r.readback();
    };
    frameAt(compute, {160, 90}, 3);
    for (const VkExtent2D size : {VkExtent2D{240, 135}, VkExtent2D{120, 68}}) {
        const app::Rgba8Image c = frameAt(compute, size, 3);
        const app::Rgba8Image h = frameAt(hardware, size, 3);
        const double matching = test::fractionOfMatchingPixels(h, c, 2);
        std::printf("%ux%u: %.2f %% of pixels within 2/255 of the hardware path's\n", size.width, size.height,
                    100.0 * matching);
        EXPECT_GE(matching, 0.995);
        ASSERT_NE(compute.recorder().impostorRaster(), nullptr);
        for (std::uint32_t slot = 0; slot < 2; ++slot) {
            const VkExtent2D e = compute.recorder().impostorRaster()->visibilityExtent(slot);
            EXPECT_EQ(e.width, size.width);
            EXPECT_EQ(e.height, size.height);
        }
    }
}

// A multisampled frame keeps the compute rasterizer (docs/compute-raster.md, "Multisampled frames"):
// the mixed crowd on its fly-over with 4 samples a pixel, meshes on the hardware (mesh limit 0) and
// impostors in compute under auto. Its resolve writes each covered pixel to all of its samples, so
// over the pixels the impostors cover, the picture is the single-sampled one's (95 % within 2/255:
// where a multisampled mesh edge crosses such a pixel, the two differ). And the meshes keep their
// anti-aliasing: against the same frame drawn wholly on the hardware with 4 samples (impostors by
// alpha to coverage), the pixels the impostors do not cover are closer than the single-sampled
// frame's by more than 2 dB (lavapipe: 34.31 against 31.37 dB; the rest of the difference is the
// hardware impostors' coverage outside the compute path's half cut).
TEST_F(GpuTest, AMultisampledFrameKeepsTheComputeRasterizer) {
    const VkSampleCountFlags counts =
        device->properties.limits.framebufferColorSampleCounts & device->properties.limits.framebufferDepthSampleCounts;
    if (!(counts & VK_SAMPLE_COUNT_4_BIT)) GTEST_SKIP() << device->description.name << " cannot render 4 samples";
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    crowd::Crowd crowd = test::mixedCrowd(soldier, horse, 1200);
    test::RendererOptions options = rasterOptions({480, 270}, render::RasterMode::Auto);
    options.meshRasterLimitPixels = 0.0f;
    test::TestRenderer single(*device, crowd, options);
    options.atlas = single.impostorAtlas();
    options.target.samples = VK_SAMPLE_COUNT_4_BIT;
    test::TestRenderer multi(*device, crowd, options);
    options.raster = render::RasterMode::Hardware;
    test::TestRenderer hardware(*device, crowd, options);
    EXPECT_EQ(multi.recorder().raster(), render::RasterMode::Auto);
    ASSERT_NE(multi.recorder().impostorRaster(), nullptr);
    for (test::TestRenderer* r : {&single, &multi, &hardware})
        r->camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 480.0f / 270.0f, 3.0);
    const RasterFrame s = renderFrame(*context, single, 11.0);
    const RasterFrame m = renderFrame(*context, multi, 11.0);
    const RasterFrame h = renderFrame(*context, hardware, 11.0);
    EXPECT_GT(m.lods.characters[0] + m.lods.characters[1] + m.lods.characters[2], 20u);
    EXPECT_GT(m.split.computeCount, 50u);
    std::size_t covered = 0, coveredClose = 0, opaque = 0;
    for (std::size_t i = 0; i < m.visibility.size(); ++i) {
        opaque += m.image.pixels.at(i * 4 + 3) == 255 ? 1 : 0;
        if (m.visibility[i] == kEmpty) continue;
        ++covered;
        coveredClose += test::pixelWithin(s.image, m.image, i, 2) ? 1 : 0;
    }
    const double close = double(coveredClose) / double(std::max<std::size_t>(covered, 1));
    // Elsewhere (the hardware-drawn meshes and ground): the covered pixels are made equal to the
    // reference's in both pictures, so that the PSNR grades only what the hardware drew.
    app::Rgba8Image multiElsewhere = m.image, singleElsewhere = s.image;
    for (std::size_t i = 0; i < m.visibility.size(); ++i)
        if (m.visibility[i] != kEmpty)
            for (std::size_t c = 0; c < 4; ++c)
                multiElsewhere.pixels[i * 4 + c] = singleElsewhere.pixels[i * 4 + c] = h.image.pixels.at(i * 4 + c);
    const double psnrMulti = app::compareImages(h.image, multiElsewhere).psnr;
    const double psnrSingle = app::compareImages(h.image, singleElsewhere).psnr;
    std::printf("%u impostors in compute cover %zu pixels, %.2f %% of them within 2/255 of the single-sampled "
                "frame; elsewhere, against the hardware's 4 samples: %.2f dB with 4 samples, %.2f dB with 1\n",
                m.split.computeCount, covered, 100.0 * close, psnrMulti, psnrSingle);
    EXPECT_GT(covered, 1000u);
    EXPECT_GE(close, 0.95);
    EXPECT_GT(psnrMulti, psnrSingle + 2.0);
    EXPECT_EQ(opaque, m.visibility.size()) << "the resolved picture must stay opaque";
    if (HasFailure() || std::getenv("CROWD_KEEP_IMAGES")) test::keepRasterImages("raster-multisampled", h.image, m.image);
}

// The programs: --raster takes hardware, compute or auto; a bad name is refused in one line with
// status 1; compute draws with validation silent, with multisampling too.
TEST_F(GpuTest, RasterFlagIsCheckedInOneLineByEveryProgram) {
    const char* deviceName = std::getenv("CROWD_TEST_DEVICE");
    const std::string deviceFlag = deviceName ? std::string(" --device '") + deviceName + "'" : "";
    auto expectOneLine = [&](const std::string& program, const std::string& arguments, const std::string& mention) {
        const test::ProgramResult r = test::runProgram(program, arguments + deviceFlag);
        EXPECT_EQ(r.exitCode, 1) << arguments << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << arguments << " printed:\n" << r.err;
        EXPECT_NE(r.err.find(mention), std::string::npos) << arguments << " printed:\n" << r.err;
    };
    const std::string render = CROWD_RENDER_BINARY, bench = CROWD_BENCH_BINARY;
    for (const std::string& program : {render, bench}) {
        expectOneLine(program, "--raster sideways", "--raster: 'sideways' is not hardware, compute or auto");
        expectOneLine(program, "--mesh-raster-limit -4", "--mesh-raster-limit");
        expectOneLine(program, "--mesh-raster-limit wide", "--mesh-raster-limit");
    }
#ifdef CROWD_VIEW_BINARY
    expectOneLine(CROWD_VIEW_BINARY, "--raster on", "--raster: 'on' is not hardware, compute or auto");
#endif
    const VkSampleCountFlags counts =
        device->properties.limits.framebufferColorSampleCounts & device->properties.limits.framebufferDepthSampleCounts;
    const std::string small = "--count 16 --frames 1 --size 64x64 --impostors on --out /dev/null";
    if (counts & VK_SAMPLE_COUNT_4_BIT) {
        for (const char* raster : {"compute", "auto"}) {
            const test::ProgramResult r =
                test::runProgram(render, small + " --aa msaa4 --raster " + raster + " --validation" + deviceFlag);
            EXPECT_EQ(r.exitCode, 0) << raster << ": " << r.err;
            EXPECT_NE(r.out.find(std::string("raster ") + raster), std::string::npos) << r.out;
        }
    }
    const test::ProgramResult r = test::runProgram(render, small + " --raster compute --validation" + deviceFlag);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("raster compute"), std::string::npos) << r.out;
    // Small meshes in compute under auto, impostors off, validation silent.
    const test::ProgramResult meshes = test::runProgram(
        render, "--count 16 --frames 2 --size 64x64 --mesh-raster-limit 64 --method compute --validation --out /dev/null" + deviceFlag);
    EXPECT_EQ(meshes.exitCode, 0) << meshes.err;
}
