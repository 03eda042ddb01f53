// Impostors that blend (issue 19): an impostor shows a weighted mix of the atlas cells of the two
// nearest azimuths, the two nearest elevation bands and the two nearest animation frames, so a turning,
// walking or risen-above impostor changes smoothly instead of jumping a view (22.5 degrees), a band
// (22.5 degrees) or a frame (1/16 of a cycle) at once.
//
// What is measured is the frame-to-frame change: the mean absolute difference of consecutive frames
// (8-bit levels, over RGB). The bounds were set from lavapipe's figures with and without the blend
// (written next to each bound), with slack on the blended side and below the unblended figure, so the
// tests fail on a nearest-cell impostor.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "app/image_downsample.h"
#include "support/character_change.h"
#include "support/gpu_test.h"

namespace {

using test::characterChange;
using test::characterMask;
using test::GpuTest;

constexpr float kDegree = 3.14159265f / 180.0f;

// The fraction of the pixels the character covers in either frame whose colour changes by more than
// `levels` in some channel from one frame to the next: a jump, where smooth motion changes a pixel by a
// little each frame.
double jumpFraction(const app::Rgba8Image& a, const app::Rgba8Image& b, const std::vector<bool>& maskA,
                    const std::vector<bool>& maskB, int levels) {
    std::size_t pixels = 0, jumps = 0;
    for (std::size_t p = 0; p < maskA.size(); ++p) {
        if (!maskA[p] && !maskB[p]) continue;
        ++pixels;
        bool jump = false;
        for (int c = 0; c < 3; ++c) jump = jump || std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c])) > levels;
        jumps += jump ? 1 : 0;
    }
    return static_cast<double>(jumps) / static_cast<double>(std::max<std::size_t>(pixels, 1));
}

// One soldier at the origin as an impostor 40 px across in a 96x96 picture (lit, or dimmed to find its
// pixels), watched from `elevation` degrees up (20 unless given) at azimuth `azimuth` (degrees) at scene
// time `time`, drawn by the hardware rasterizer or the compute one (`raster`).
struct OneImpostor {
    explicit OneImpostor(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, bool impostors,
                         bool blend = true, render::RasterMode raster = render::RasterMode::Hardware)
        : soldier(soldier), lit(soldier, characters(soldier, 1.0f)), dim(soldier, characters(soldier, 0.6f)) {
        test::RendererOptions options;
        options.size = {96, 96};
        options.method = skin::Method::Compute;
        options.impostorBlend = blend;
        options.raster = raster;
        options.cull.impostors = impostors;
        options.cull.impostorThreshold = 49.0f;
        options.cull.hysteresis = 0.0f;
        litRenderer = std::make_unique<test::TestRenderer>(context, lit, options);
        if (impostors) options.atlas = litRenderer->impostorAtlas();
        dimRenderer = std::make_unique<test::TestRenderer>(context, dim, options);
    }
    static std::vector<crowd::Character> characters(const model::SkinnedModel& soldier, float tint) {
        crowd::Character c;
        c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
        c.tint = glm::vec3(tint);
        return {c};
    }
    struct Frame {
        app::Rgba8Image picture;
        std::vector<bool> mask;
    };
    Frame frame(float azimuth, float time, float elevation = 20.0f) {
        render::Camera camera;
        const float focal = 96.0f / (2.0f * std::tan(0.5f * camera.verticalFov));
        const float distance = 2.0f * soldier.poseSphere.w * focal / 40.0f;
        camera.target = glm::vec3(0.0f, glm::vec3(soldier.poseSphere).y, 0.0f);
        const float a = azimuth * kDegree, e = elevation * kDegree;
        camera.eye = camera.target + distance * glm::vec3(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
        camera.nearPlane = 0.5f;
        camera.farPlane = 4.0f * distance;
        app::Rgba8Image pictures[2];
        for (int i = 0; i < 2; ++i) {
            test::TestRenderer& renderer = i == 0 ? *litRenderer : *dimRenderer;
            renderer.camera = test::appCamera(camera);
            renderer.renderFrame(time);
            renderer.finish();
            renderer.takeStats();
            pictures[i] = renderer.readback();
        }
        return {pictures[0], characterMask(pictures[0], pictures[1])};
    }
    const model::SkinnedModel& soldier;
    crowd::Crowd lit, dim;
    std::unique_ptr<test::TestRenderer> litRenderer, dimRenderer;
};

struct Changes {
    double largest = 0.0, mean = 0.0;
};

// Frame-to-frame change of the character over a sequence of (azimuth, time, elevation) steps.
Changes sequenceChanges(OneImpostor& one, const std::vector<glm::vec3>& steps, const std::string& name) {
    Changes changes;
    OneImpostor::Frame previous = one.frame(steps[0].x, steps[0].y, steps[0].z);
    for (std::size_t k = 1; k < steps.size(); ++k) {
        OneImpostor::Frame next = one.frame(steps[k].x, steps[k].y, steps[k].z);
        const double change = characterChange(previous.picture, next.picture, previous.mask, next.mask);
        changes.largest = std::max(changes.largest, change);
        changes.mean += change / static_cast<double>(steps.size() - 1);
        if (std::getenv("CROWD_KEEP_IMAGES"))
            app::writePng(test::artifactPath(name + "-" + std::to_string(k) + ".png"), next.picture);
        previous = std::move(next);
    }
    return changes;
}

}  // namespace

// One soldier drawn as an impostor, standing still while the camera circles it by 1 degree a frame
// through 45 degrees (two view boundaries), then walking in place seen from a fixed camera at 60 frames
// a second through a whole cycle (16 frame boundaries): the character's pixels change by at most a
// bound from one frame to the next. The mesh of the same soldier is measured alongside for scale.
TEST_F(GpuTest, ATurningOrWalkingImpostorChangesSmoothly) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const float duration = soldier.clips[static_cast<std::size_t>(soldier.findClip("walk"))].duration;
    std::vector<glm::vec3> turning, walking;
    for (int k = 0; k <= 45; ++k) turning.push_back({3.0f + static_cast<float>(k), 0.4f, 20.0f});
    for (int k = 0; k <= static_cast<int>(duration * 60.0f); ++k)
        walking.push_back({3.0f, static_cast<float>(k) / 60.0f, 20.0f});
    Changes measured[2][2];  // [impostor][turning, walking]
    for (const bool impostors : {false, true}) {
        OneImpostor one(*context, soldier, impostors);
        measured[impostors][0] = sequenceChanges(one, turning, impostors ? "turning-impostor" : "turning-mesh");
        measured[impostors][1] = sequenceChanges(one, walking, impostors ? "walking-impostor" : "walking-mesh");
    }
    for (int s = 0; s < 2; ++s)
        std::printf("%s: frame-to-frame change of the character's pixels, largest / mean: impostor %.2f / %.2f, "
                    "mesh %.2f / %.2f\n", s == 0 ? "turning 1 degree a frame" : "walking at 60 fps",
                    measured[1][s].largest, measured[1][s].mean, measured[0][s].largest, measured[0][s].mean);
    // Lavapipe, largest change: turning 2.93 blended (3.25 before the elevation bands were blended; the
    // mesh's 4.40), 21.69 with the nearest cell; walking 4.63 blended (4.32; the mesh's 4.99), 11.66 with
    // the nearest frame.
    EXPECT_LT(measured[1][0].largest, 8.0);
    EXPECT_LT(measured[1][1].largest, 7.5);
}

// The switch back (--impostor-blend off, RendererSettings::impostorBlend): the same turning and walking
// impostor shows the nearest cell again, so it jumps at the view and frame boundaries that the blend
// smooths. Lavapipe, largest change: turning 21.69 (blended 2.93), walking 11.66 (blended 4.63), as
// before the blend existed; the bounds are the blended test's, which the nearest cell must exceed.
TEST_F(GpuTest, ImpostorBlendOffShowsTheNearestCellAgain) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const float duration = soldier.clips[static_cast<std::size_t>(soldier.findClip("walk"))].duration;
    std::vector<glm::vec3> turning, walking;
    for (int k = 0; k <= 45; ++k) turning.push_back({3.0f + static_cast<float>(k), 0.4f, 20.0f});
    for (int k = 0; k <= static_cast<int>(duration * 60.0f); ++k)
        walking.push_back({3.0f, static_cast<float>(k) / 60.0f, 20.0f});
    OneImpostor one(*context, soldier, true, false);
    const Changes turned = sequenceChanges(one, turning, "turning-nearest");
    const Changes walked = sequenceChanges(one, walking, "walking-nearest");
    std::printf("nearest cell: largest frame-to-frame change turning %.2f, walking %.2f\n", turned.largest, walked.largest);
    EXPECT_GT(turned.largest, 8.0);
    EXPECT_GT(walked.largest, 7.5);
}

// The elevation bands (4 of 22.5 degrees, each captured at its middle): one still soldier (scene time
// held) seen from a camera rising from 10 to 35 degrees at 0.5 degree a frame at a constant distance,
// through the band edge at 22.5 degrees where the nearest cell switches from band 0's picture (captured
// from 11.25 degrees up) to band 1's (33.75). Blended, the picture moves from one band's to the next
// between their middles; the largest frame-to-frame change over the character's pixels stays under a
// bound with the hardware rasterizer and the compute one, and exceeds it with --impostor-blend off
// (the band switch). The mesh of the same soldier is measured alongside for scale.
TEST_F(GpuTest, ACameraRisingThroughAnElevationBandEdgeChangesSmoothly) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    std::vector<glm::vec3> rising;
    for (int k = 0; k <= 50; ++k) rising.push_back({3.0f, 0.4f, 10.0f + 0.5f * static_cast<float>(k)});
    OneImpostor mesh(*context, soldier, false);
    const Changes meshChanges = sequenceChanges(mesh, rising, "rising-mesh");
    OneImpostor hardware(*context, soldier, true, true, render::RasterMode::Hardware);
    const Changes blended = sequenceChanges(hardware, rising, "rising-impostor");
    OneImpostor compute(*context, soldier, true, true, render::RasterMode::Compute);
    const Changes blendedCompute = sequenceChanges(compute, rising, "rising-impostor-compute");
    OneImpostor off(*context, soldier, true, false);
    const Changes nearest = sequenceChanges(off, rising, "rising-nearest");
    std::printf("rising 0.5 degree a frame through 22.5 degrees: frame-to-frame change of the character's pixels, "
                "largest / mean: blended %.2f / %.2f (compute raster %.2f / %.2f), nearest cell %.2f / %.2f, "
                "mesh %.2f / %.2f\n", blended.largest, blended.mean, blendedCompute.largest, blendedCompute.mean,
                nearest.largest, nearest.mean, meshChanges.largest, meshChanges.mean);
    // Lavapipe, largest change: blended 1.73 with either rasterizer (the mesh's 2.07), 14.46 with the
    // nearest cell (and with the four-cell blend of views and frames before the bands were blended).
    constexpr double kBound = 4.0;
    EXPECT_LT(blended.largest, kBound);
    EXPECT_LT(blendedCompute.largest, kBound);
    EXPECT_GT(nearest.largest, kBound);
}

// A still crowd of impostors (scene time held) under a camera orbiting it slowly, 0.045 degrees a frame
// (the Orbit path in steps of 5 ms) at half the framed distance (far soldiers 10-20 px tall, every one
// an impostor), with 4 samples a pixel: over the far field (the upper half of the picture) where
// soldiers stand (the pixels their tint changes, in either frame), the mean frame-to-frame change is
// under 0.72 times the change of the 4x4 supersampled render of the same frames with meshes (the
// picture the impostors stand in for, filtered: what a viewer should see change). The impostors are
// softer than the meshes (their cells are box-filtered mips), so their smooth change is the smaller;
// a view switching at once adds to it. Lavapipe: 0.68 blended (0.72 before the elevation bands were
// blended), 0.77 with the nearest cell.
// Multisampled because single-sampled every edge in the far field flickers from aliasing as the camera
// moves, which swamps the switches (1.30 against 1.34 at 1 sample and 0.18 degrees a frame).
TEST_F(GpuTest, AnOrbitOverAStillImpostorCrowdChangesLikeItsSupersampledRender) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 400;
    std::vector<crowd::Character> characters = test::buildCharacters(soldier, scene);
    crowd::Crowd litCrowd(soldier, characters), meshCrowd(soldier, characters);
    for (crowd::Character& c : characters) c.tint *= 0.6f;
    crowd::Crowd dimCrowd(soldier, characters);
    constexpr VkExtent2D kSize{192, 108};
    test::RendererOptions options;
    options.size = kSize;
    options.method = skin::Method::Compute;
    options.cull.lodThresholds[0] = 400.0f;
    options.cull.lodThresholds[1] = 300.0f;
    options.cull.impostorThreshold = 200.0f;  // every soldier in the picture an impostor
    options.cull.impostors = true;
    options.target.samples = VK_SAMPLE_COUNT_4_BIT;
    test::TestRenderer lit(*context, litCrowd, options);
    options.atlas = lit.impostorAtlas();
    test::TestRenderer dim(*context, dimCrowd, options);
    options.size = {kSize.width * 4, kSize.height * 4};
    options.cull.impostors = false;
    options.target.samples = VK_SAMPLE_COUNT_1_BIT;
    test::TestRenderer meshes(*context, meshCrowd, options);
    const app::CrowdShape shape = test::shapeOf(litCrowd);
    const std::uint32_t rows = kSize.height / 2;
    constexpr int kFrames = 32;
    app::Rgba8Image previous[2];
    std::vector<bool> previousMask;
    double mean[2] = {0.0, 0.0}, largest[2] = {0.0, 0.0}, jumps[2] = {0.0, 0.0};
    std::uint32_t impostorCount = 0;
    for (int k = 0; k < kFrames; ++k) {
        app::Camera camera = app::cameraOnPath(app::CameraPath::Orbit, shape, 16.0f / 9.0f, 2.0 + 0.005 * k);
        camera.eye = camera.target + 0.5f * (camera.eye - camera.target);
        app::Rgba8Image pictures[3];  // impostors, supersampled meshes, dimmed impostors
        for (int i = 0; i < 3; ++i) {
            test::TestRenderer& renderer = i == 0 ? lit : i == 1 ? meshes : dim;
            renderer.camera = camera;
            renderer.renderFrame(11.0);
            renderer.finish();
            const auto stats = renderer.takeStats();
            if (i == 0) impostorCount = stats.back().lods.impostors;
            pictures[i] = i == 1 ? app::boxDownsample(renderer.readback(), 4) : renderer.readback();
        }
        std::vector<bool> mask = characterMask(pictures[0], pictures[2]);
        mask.resize(std::size_t{kSize.width} * rows);  // the far field
        for (int i = 0; i < 2 && k > 0; ++i) {
            const double change = characterChange(previous[i], pictures[i], previousMask, mask);
            mean[i] += change / (kFrames - 1);
            largest[i] = std::max(largest[i], change);
            jumps[i] += jumpFraction(previous[i], pictures[i], previousMask, mask, 32) / (kFrames - 1);
        }
        if (std::getenv("CROWD_KEEP_IMAGES")) {
            app::writePng(test::artifactPath("orbit-impostors-" + std::to_string(k) + ".png"), pictures[0]);
            app::writePng(test::artifactPath("orbit-supersampled-" + std::to_string(k) + ".png"), pictures[1]);
        }
        for (int i = 0; i < 2; ++i) previous[i] = std::move(pictures[i]);
        previousMask = std::move(mask);
    }
    std::printf("orbit over %u impostors: far-field frame-to-frame change where soldiers stand, mean / largest / "
                "share of pixels jumping over 32 levels: impostors %.3f / %.3f / %.4f, supersampled meshes "
                "%.3f / %.3f / %.4f; ratio of means %.2f\n", impostorCount, mean[0], largest[0], jumps[0], mean[1],
                largest[1], jumps[1], mean[0] / mean[1]);
    EXPECT_GT(impostorCount, 300u);
    EXPECT_GT(mean[1], 0.5);  // the camera does move
    EXPECT_LT(mean[0], 0.72 * mean[1]);
}
