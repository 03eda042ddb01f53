// No pops (issue 19): a character whose size crosses a level-of-detail threshold or the impostor
// threshold changes across a band of sizes (set by the hysteresis), so that its picture changes a
// little each frame instead of all at once: between mesh levels the finer level morphs into the
// coarser one just above the threshold (shaders/lod_morph.glsl.inc); into the impostor both are drawn,
// each on a complementary screen-space dither of its pixels (gpu_types.h FADE_SHIFT,
// shaders/cull.glsl.inc fadeShare, shaders/fade_dither.glsl.inc).
//
// The frame-to-frame change is the mean absolute difference of consecutive frames over RGB, in 8-bit
// levels, over the pixels the character covers in either frame (support/character_change.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "crowd/cull_reference.h"
#include "support/character_change.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

// Thresholds 150 and 50 px, 10 % band, impostors below 32 px.
const glm::vec4 kLod{150.0f, 50.0f, 0.1f, 32.0f};

std::uint32_t fadeStep(std::uint32_t state) { return state >> FADE_SHIFT; }

}  // namespace

// The rule by hand. Between mesh levels: above a threshold's band (T to 1.2 T) the character is at the
// finer level and not fading; in it, at the finer level with the coarser's share rising linearly from 0
// at the band's top to 1 at T, in 64ths (FADE_STEPS); below T, at the coarser level. Into the impostor
// the band is centred on the threshold (0.9 T to 1.1 T). The last mesh level fades into the impostor
// only when impostors are on; the impostor level never fades.
TEST(FadeRule, CoarserShareRisesLinearlyAcrossTheHysteresisBand) {
    EXPECT_EQ(crowd::fadedLod(185.0f, kLod), 0u);
    EXPECT_EQ(crowd::fadeShare(185.0f, 0, kLod), 0u);
    EXPECT_EQ(crowd::fadedLod(180.0f, kLod), 0u);
    EXPECT_EQ(crowd::fadeShare(180.0f, 0, kLod), 0u);         // the band's top: (180 - 180) / 30
    static_assert(FADE_STEPS == 64u, "the shares below are hand-computed in 64ths");
    EXPECT_EQ(crowd::fadeShare(165.0f, 0, kLod), 32u);        // the band's middle: half
    EXPECT_EQ(crowd::fadeShare(172.5f, 0, kLod), 16u);        // a quarter
    EXPECT_EQ(crowd::fadedLod(150.5f, kLod), 0u);
    EXPECT_EQ(crowd::fadeShare(150.5f, 0, kLod), 63u);        // 29.5 / 30 of the way: 62.9 rounds to 63
    EXPECT_EQ(crowd::fadedLod(150.0f, kLod), 0u);
    EXPECT_EQ(crowd::fadeShare(150.0f, 0, kLod), 64u);        // the threshold: fully morphed
    EXPECT_EQ(crowd::fadedLod(149.5f, kLod), 1u);             // below T: the coarser level, whole
    EXPECT_EQ(crowd::fadeShare(149.5f, 1, kLod), 0u);
    EXPECT_EQ(crowd::fadedLod(55.0f, kLod), 1u);
    EXPECT_EQ(crowd::fadeShare(55.0f, 1, kLod), 32u);
    EXPECT_EQ(crowd::fadedLod(32.0f, kLod), 2u);               // LOD 2 fading into the impostor
    EXPECT_EQ(crowd::fadeShare(32.0f, 2, kLod), 32u);
    EXPECT_EQ(crowd::fadedLod(28.0f, kLod), IMPOSTOR_LEVEL);
    EXPECT_EQ(crowd::fadeShare(28.0f, IMPOSTOR_LEVEL, kLod), 0u);
    const glm::vec4 noImpostors{150.0f, 50.0f, 0.1f, 0.0f};
    EXPECT_EQ(crowd::fadedLod(32.0f, noImpostors), 2u);
    EXPECT_EQ(crowd::fadeShare(32.0f, 2, noImpostors), 0u);
    const glm::vec4 noBand{150.0f, 50.0f, 0.0f, 32.0f};        // no band: nothing fades
    EXPECT_EQ(crowd::fadeShare(150.0f, 0, noBand), 0u);
}

namespace {

// A level or impostor change is a band of sizes; decisions at the band's edges and at the 1/FADE_STEPS
// steps within it, as well as the frustum's planes, may round either way between CPU and GPU.
float decisionMargin(const gpu::CullUniforms& u, const gpu::CharacterRecord& c, const gpu::ModelRecord& m) {
    const glm::vec4 sphere = crowd::worldSphere(c, m);
    float margin = 1e30f;
    for (const glm::vec4& p : u.planes)
        margin = std::min(margin, std::abs(glm::dot(glm::vec3(p), glm::vec3(sphere)) + p.w + sphere.w) /
                                      std::max(sphere.w, 1e-3f));
    const float size = crowd::projectedDiameter(sphere, u.camera);
    for (float t : {u.lod.x, u.lod.y, u.lod.w}) {
        if (t <= 0.0f) continue;
        const float top = t == u.lod.w ? 1.0f + u.lod.z : 1.0f + 2.0f * u.lod.z;  // cull.glsl.inc, fadeShare
        for (std::uint32_t k = 0; k <= 2 * FADE_STEPS; ++k) {  // the band's edges and every half-step
            const float s = t * (top - 2.0f * u.lod.z * static_cast<float>(k) / (2.0f * FADE_STEPS));
            margin = std::min(margin, std::abs(size - s) / s);
        }
    }
    return margin;
}

}  // namespace

// A crowd of 900 flown over with impostors, a wide band (25 %) so that many characters fade at each
// threshold, and a mesh cap that demotes some (a demoted character's fade is dropped): the GPU's lists (visible per bucket, impostors in view: a character fading into its
// impostor is in both), states (fade steps included) and count of characters morphing between mesh levels equal the CPU
// reference's, except characters within 1e-4 of a decision.
TEST_F(GpuTest, FadesEqualTheCpuReferenceAlongACameraPath) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 900;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.cull.lodThresholds[0] = 20.0f;  // sizes a 90-pixel image shows, so every band is crossed:
    options.cull.lodThresholds[1] = 12.0f;  // 20-30, 12-18 and 6.75-11.25 px
    options.cull.impostors = true;
    options.cull.impostorThreshold = 9.0f;
    options.cull.hysteresis = 0.25f;
    options.meshCapacity = 100;  // the cut demotes some (their fades dropped: impostors drawn whole)
    test::TestRenderer renderer(*device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    std::uint32_t fadingPerLevel[LOD_COUNT] = {}, morphing = 0, demoted = 0;
    for (float seconds : {0.0f, 4.0f, 8.0f, 12.0f, 16.0f, 20.0f}) {
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, shape, 160.0f / 90.0f, seconds);
        renderer.renderFrame(seconds);
        renderer.finish();
        const gpu::CullUniforms uniforms = renderer.cullUniforms();
        ASSERT_EQ(uniforms.fade.x, 1u);
        std::vector<std::uint32_t> cpuState(crowd.size(), 0u), cpuImpostors;
        crowd::ShadowLists expected;
        std::uint32_t cpuDemoted = 0;
        const crowd::VisibleLists expectedVisible = crowd::cullOnCpu(uniforms, renderer.buffers().records(),
                                                                     renderer.pool().models(), cpuState, &cpuImpostors,
                                                                     &cpuDemoted, &expected);
        demoted += cpuDemoted;
        const crowd::VisibleLists gpuVisible = test::readVisibleLists(*context, renderer);
        const std::vector<std::uint32_t> gpuImpostors = test::readImpostorList(*context, renderer);
        const crowd::ShadowLists gpu = test::readShadowLists(*context, renderer);
        const gpu::ModelRecord& model = renderer.pool().models()[0];
        auto expectNearDecision = [&](std::uint32_t c, const char* what) {
            EXPECT_LT(decisionMargin(uniforms, renderer.buffers().records()[c], model), 1e-4f)
                << "character " << c << " at " << seconds << " s: " << what << " differs";
        };
        for (std::size_t b = 0; b < expectedVisible.size(); ++b)
            for (std::uint32_t c : test::differ(expectedVisible[b], gpuVisible[b])) expectNearDecision(c, "its bucket");
        for (std::uint32_t c : test::differ(cpuImpostors, gpuImpostors)) expectNearDecision(c, "its impostor");
        std::uint32_t expectedMorphs = 0;
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            if (gpu.states[c] != expected.states[c]) expectNearDecision(c, "its state");
            const std::uint32_t level = cpuState[c] - 1u;
            if (fadeStep(expected.states[c]) == 0u || !(expected.states[c] & SHADOW_IN_VIEW_BIT)) continue;
            ++fadingPerLevel[level];
            if (level + 1u < LOD_COUNT) ++expectedMorphs;
        }
        std::uint32_t totals[8];
        const std::vector<std::byte> bytes = test::readBuffer(*context, renderer.drawLists().totals());
        std::memcpy(totals, bytes.data(), sizeof totals);
        EXPECT_NEAR(static_cast<double>(totals[offsetof(gpu::DrawTotals, morphCount) / 4]), expectedMorphs, 2.0)
            << "characters morphing between mesh levels at " << seconds << " s";
        morphing += expectedMorphs;
    }
    std::printf("fading characters in view, summed over the path: from LOD 0 %u, LOD 1 %u, LOD 2 %u (into impostors)\n",
                fadingPerLevel[0], fadingPerLevel[1], fadingPerLevel[2]);
    // Not a trivial path: every threshold has characters fading across it.
    for (std::uint32_t level = 0; level < LOD_COUNT; ++level) EXPECT_GT(fadingPerLevel[level], 0u) << "level " << level;
    EXPECT_GT(morphing, 0u);
    EXPECT_GT(demoted, 0u);
    std::printf("demoted by the mesh cap, summed over the path: %u\n", demoted);
}

namespace {

// One soldier, standing at the origin in a still pose, in a 128x128 picture (lit, or dimmed to find its
// pixels), seen from 20 degrees up at a distance that makes its pose sphere `size` pixels across.
struct OneSoldier {
    OneSoldier(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, bool fades)
        : soldier(soldier), lit(soldier, characters(soldier, 1.0f)), dim(soldier, characters(soldier, 0.6f)) {
        test::RendererOptions options;
        options.size = {128, 128};
        options.method = skin::Method::Compute;
        options.shadows = false;  // the character's own pixels only
        options.cull.lodThresholds[0] = 90.0f;
        options.cull.lodThresholds[1] = 60.0f;
        options.cull.impostors = true;
        options.cull.impostorThreshold = 40.0f;
        options.cull.hysteresis = 0.1f;
        options.cull.lodFade = fades;
        litRenderer = std::make_unique<test::TestRenderer>(context, lit, options);
        options.atlas = litRenderer->impostorAtlas();
        dimRenderer = std::make_unique<test::TestRenderer>(context, dim, options);
    }
    static std::vector<crowd::Character> characters(const model::SkinnedModel& soldier, float tint) {
        crowd::Character c;
        c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
        c.speed = 0.0f;  // a still pose: only the distance changes
        c.timeOffset = 0.3f;
        c.tint = glm::vec3(tint);
        return {c};
    }
    struct Frame {
        app::Rgba8Image picture;
        std::vector<bool> mask;
    };
    Frame frame(float size) {
        render::Camera camera;
        const float focal = 128.0f / (2.0f * std::tan(0.5f * camera.verticalFov));
        const float distance = 2.0f * soldier.poseSphere.w * focal / size;
        camera.target = glm::vec3(soldier.poseSphere);
        const float a = 30.0f * kDegree, e = 20.0f * kDegree;
        camera.eye = camera.target + distance * glm::vec3(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
        camera.nearPlane = 0.5f;
        camera.farPlane = 4.0f * distance;
        app::Rgba8Image pictures[2];
        for (int i = 0; i < 2; ++i) {
            test::TestRenderer& renderer = i == 0 ? *litRenderer : *dimRenderer;
            renderer.camera = test::appCamera(camera);
            renderer.renderFrame(0.0f);
            renderer.finish();
            renderer.takeStats();
            pictures[i] = renderer.readback();
        }
        return {pictures[0], test::characterMask(pictures[0], pictures[1])};
    }
    static constexpr float kDegree = 3.14159265f / 180.0f;
    const model::SkinnedModel& soldier;
    crowd::Crowd lit, dim;
    std::unique_ptr<test::TestRenderer> litRenderer, dimRenderer;
};

// The largest frame-to-frame change of the soldier as the camera backs away so that its size falls
// from `from` to `to` pixels in `frames` equal ratios.
double largestChange(OneSoldier& one, float from, float to, int frames, const std::string& name) {
    double largest = 0.0;
    OneSoldier::Frame previous = one.frame(from);
    for (int k = 1; k <= frames; ++k) {
        const float size = from * std::pow(to / from, static_cast<float>(k) / static_cast<float>(frames));
        OneSoldier::Frame next = one.frame(size);
        largest = std::max(largest, test::characterChange(previous.picture, next.picture, previous.mask, next.mask));
        if (std::getenv("CROWD_KEEP_IMAGES"))
            app::writePng(test::artifactPath(name + "-" + std::to_string(k) + ".png"), next.picture);
        previous = std::move(next);
    }
    return largest;
}

}  // namespace

// The end of a band between mesh levels: the finer level fully morphed (shaders/lod_morph.glsl.inc)
// must look like the coarser level that follows it, or the fade ends in a pop. The soldier steps from
// just above the level's switch to just below it (the coarser level), 0.2 % smaller, for LOD 0 -> 1
// (T = 90 px) and LOD 1 -> 2 (T = 60 px), after a frame above the band. With fades the switch is at T,
// where the morph ends; without, hysteresis keeps the finer level down to 0.9 T, and the switch is there.
// Against the same step in size at the coarser level alone, the step out of the band may change the
// soldier's pixels only a little more with fades (the two levels' triangles meet the pixels a little
// differently), and changes them a lot more without.
TEST_F(GpuTest, AFullyMorphedLevelLooksLikeTheCoarserLevelThatFollowsIt) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const float thresholds[2] = {90.0f, 60.0f};
    double leaving[2][2], zoom[2];  // [edge][fades], [edge]
    for (const bool fades : {false, true}) {
        OneSoldier one(*context, soldier, fades);
        for (int e = 0; e < 2; ++e) {
            const float edge = thresholds[e] * (fades ? 1.0f : 0.9f);
            one.frame(thresholds[e] * 1.3f);
            const OneSoldier::Frame above = one.frame(edge * 1.001f), below = one.frame(edge * 0.999f);
            leaving[e][fades] = test::characterChange(above.picture, below.picture, above.mask, below.mask);
            if (!fades) continue;
            const OneSoldier::Frame further = one.frame(edge * 0.997f);
            zoom[e] = test::characterChange(below.picture, further.picture, below.mask, further.mask);
        }
    }
    std::printf("leaving the band, against the size step alone: LOD 0 -> 1 %.2f with fades (morphed), %.2f without, "
                "%.2f the step; LOD 1 -> 2 %.2f, %.2f, %.2f\n",
                leaving[0][1], leaving[0][0], zoom[0], leaving[1][1], leaving[1][0], zoom[1]);
    // Lavapipe: LOD 0 -> 1 1.63 with fades, 4.78 without, 0.82 the step alone; LOD 1 -> 2 1.90, 7.13,
    // 0.45. With the band centred on T (its end at 0.9 T, where the soldier is smaller): 1.55, 4.78,
    // 1.18 and 2.08, 7.13, 0.75; at 512x512 (the soldier 4x as large) 1.34, 4.82, 0.68 and 1.65, 6.71, 0.72.
    for (int e = 0; e < 2; ++e) {
        EXPECT_LT(leaving[e][1], zoom[e] + 2.0) << "edge " << e;
        EXPECT_GT(leaving[e][0], zoom[e] + 3.0) << "edge " << e;
    }
}

// One soldier zoomed out across the LOD 0/1 threshold (its pose sphere 110 -> 80 px, threshold 90) and
// across the impostor threshold (48 -> 32 px, threshold 40), 0.5 % and 0.7 % smaller each frame: with
// fades, the largest frame-to-frame change of its pixels stays under a bound that the switch at once
// (fades off) exceeds.
TEST_F(GpuTest, ACharacterCrossingALevelOrTheImpostorThresholdDoesNotPop) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    double lodChange[2], impostorChange[2];  // [fades]
    for (const bool fades : {false, true}) {
        OneSoldier one(*context, soldier, fades);
        lodChange[fades] = largestChange(one, 110.0f, 80.0f, 60, fades ? "fade-lod" : "pop-lod");
        impostorChange[fades] = largestChange(one, 48.0f, 32.0f, 60, fades ? "fade-impostor" : "pop-impostor");
    }
    std::printf("largest frame-to-frame change of the soldier's pixels: LOD 0 -> 1 %.2f with fades, %.2f without; "
                "LOD 2 -> impostor %.2f with fades, %.2f without\n",
                lodChange[1], lodChange[0], impostorChange[1], impostorChange[0]);
    // Lavapipe: LOD 0 -> 1 2.88 with fades, 5.90 without; LOD 2 -> impostor 3.46 with fades, 14.33
    // without. The switches without fades are checked to exceed the bound, so that it tells them apart.
    // Since the props' own levels (issue 20: the body simplified apart from its props, the rifle a tube at
    // level 2) the soldier's level 2 differs more from its impostor: 2.38 / 5.92 and 4.57 / 13.77, and
    // the bound was 5.0 for a while. With the 8x8 dither (64 steps where there were 16): 2.37 / 5.92 and
    // 4.19 / 14.63, under 4.5 again (docs/picture-quality.md); with the 4x4 one this test fails. With
    // mesh levels morphing above the threshold (the sweep 110 -> 80 px to cross the band, 90-108):
    // 2.47 / 5.72 and 4.19 / 14.62.
    constexpr double kBound = 4.5;
    EXPECT_LT(lodChange[1], kBound);
    EXPECT_LT(impostorChange[1], kBound);
    EXPECT_GT(lodChange[0], kBound);
    EXPECT_GT(impostorChange[0], kBound);
}
