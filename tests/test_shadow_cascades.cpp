// The sun's shadow cascades (render/shadow_cascades.h): the view split by distance, each stretch in its
// own square of the shadow map. On the CPU: every point the camera sees, out to the shadow distance and
// up to the casters' height, is owned by a cascade (no gap), the finest one there. On lavapipe: a line of
// soldiers receding from the camera casts its shadows in every stretch of the view as a one-map
// reference of sixteen times the texels does, and the near ones closer to it than one map of the same
// texels draws them.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <set>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "render/shadow_cascades.h"
#include "render/shadow_map.h"
#include "support/gpu_test.h"
#include "support/run_program.h"

namespace {

using test::GpuTest;

struct CameraCase {
    const char* name;
    render::Camera camera;
    bool alongTheGround = true;  // the near stretch sees ground near the camera (not so looking down from high)
};

// The crowd of the default scene's size: 40 m across, soldiers 1.8 m tall.
const render::CrowdShape kCrowd{{0.0f, 0.0f, 0.0f}, 20.0f, 1.8f};

std::vector<CameraCase> cameras() {
    std::vector<CameraCase> cases(3);
    cases[0].name = "framed from outside";
    cases[0].camera.eye = {30.0f, 25.0f, 45.0f};
    cases[1].name = "inside the crowd";
    cases[1].camera.eye = {0.0f, 1.7f, 5.0f};
    cases[1].camera.target = {0.0f, 1.5f, -20.0f};
    cases[2].name = "from above";
    cases[2].camera.eye = {0.0f, 60.0f, 8.0f};
    cases[2].alongTheGround = false;
    for (CameraCase& c : cases) c.camera.verticalFov = glm::radians(50.0f), c.camera.nearPlane = 0.1f;
    return cases;
}

// The point of the view `along` from the eye (measured along the view direction) at screen position
// (sx, sy) in [-1, 1].
glm::vec3 pointInView(const render::Camera& camera, float aspect, float along, float sx, float sy) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    const float h = std::tan(0.5f * camera.verticalFov);
    return camera.eye + along * (forward + sx * h * aspect * right + sy * h * up);
}

}  // namespace

// Every point of the view from the nearest shadowed distance out to the shadow distance, from the ground
// up to three character heights above it, is owned by a cascade with the filter's reach inside its
// square, and by the one whose stretch holds it or a finer one. The stretches join end to end, and
// each cascade spends more texels a metre than the next.
TEST(ShadowCascades, CoverTheViewToTheShadowDistanceWithNoGap) {
    const float aspect = 16.0f / 9.0f;
    for (const CameraCase& c : cameras()) {
        for (std::uint32_t count = 1; count <= render::kMostShadowCascades; ++count) {
            SCOPED_TRACE(std::string(c.name) + ", " + std::to_string(count) + " cascades");
            const render::ShadowCascades cascades =
                render::shadowCascades(c.camera, aspect, kCrowd, render::lightDirection(), count, 2048);
            ASSERT_EQ(cascades.count, count);
            float texelsPerMetre = 1e30f;
            for (std::uint32_t k = 0; k < count; ++k) {
                EXPECT_LT(cascades.splits[k], cascades.splits[k + 1]);
                const float perMetre = cascades.square[k].z * 2048.0f * 0.5f * glm::length(glm::vec3(cascades.clip[k][0][0], cascades.clip[k][1][0], cascades.clip[k][2][0]));
                if (c.alongTheGround) {
                    EXPECT_LT(perMetre, texelsPerMetre) << "cascade " << k << " is no coarser than the one before";
                }
                texelsPerMetre = perMetre;
            }
            std::size_t points = 0, gaps = 0, coarser = 0;
            for (std::uint32_t k = 0; k < count; ++k) {
                for (int step = 0; step <= 16; ++step) {
                    const float along = glm::mix(cascades.splits[k], cascades.splits[k + 1], step / 16.0f);
                    // The screen's edges a thousandth in: a pixel's centre is half a pixel in, and the
                    // one-map view's box ends exactly at the screen's edge (within rounding).
                    for (int ix = 0; ix <= 16; ++ix)
                        for (int iy = 0; iy <= 16; ++iy) {
                            const float sx = 0.999f * (ix / 8.0f - 1.0f), sy = 0.999f * (iy / 8.0f - 1.0f);
                            const glm::vec3 p = pointInView(c.camera, aspect, along, sx, sy);
                            // Under the ground nothing is seen; over three heights no caster stands.
                            if (p.y < 0.0f || p.y > 3.0f * kCrowd.characterHeight) continue;
                            ++points;
                            const int owner = render::cascadeHolding(cascades, p);
                            gaps += owner < 0;
                            // At the stretch's far end (step 16) the next stretch begins: either is its own.
                            coarser += owner > static_cast<int>(k) + (step == 16 ? 1 : 0);
                        }
                }
            }
            EXPECT_GT(points, 300u);
            EXPECT_EQ(gaps, 0u) << "points of the view no cascade owns";
            EXPECT_EQ(coarser, 0u) << "points owned by a cascade coarser than their stretch's";
        }
    }
}

namespace {

// Twenty soldiers in a file walking away from a camera 6 m up, every 2.2 m from 3 m to 44.8 m ahead.
std::vector<crowd::Character> fileOfSoldiers(const model::SkinnedModel& soldier) {
    std::vector<crowd::Character> characters;
    for (int i = 0; i < 20; ++i) {
        crowd::Character c;
        c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
        c.position = {0.0f, 0.0f, -3.0f - 2.2f * static_cast<float>(i)};
        c.heading = 3.14159265f;
        c.timeOffset = 0.1f * static_cast<float>(i);
        characters.push_back(c);
    }
    return characters;
}

constexpr std::uint32_t kWidth = 480, kHeight = 270;

struct FilePicture {
    app::Rgba8Image picture;
    glm::mat4 viewProjection;
    render::ShadowCascades cascades;
};

FilePicture renderFile(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, bool shadows,
                       std::uint32_t cascades, std::uint32_t mapSize) {
    crowd::Crowd crowd(soldier, fileOfSoldiers(soldier));
    test::RendererOptions options;
    options.size = {kWidth, kHeight};
    options.method = skin::Method::Compute;
    options.shadows = shadows;
    options.shadowCascades = cascades;
    options.shadowMapSize = mapSize;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera.eye = {-1.5f, 6.0f, 2.0f};
    renderer.camera.target = {0.5f, 0.0f, -25.0f};
    renderer.renderFrame(0.5);
    const render::FrameView view = render::frameViewOf(test::internalCamera(renderer.camera), renderer.extent(), 0.5);
    return {renderer.readback(), view.projection * view.view, renderer.recorder().shadowCascadesOf(view)};
}

// Whether shadows darkened a pixel within two of (x, y), by more than 4 of 255 in every channel.
bool darkenedNear(const app::Rgba8Image& shadowed, const app::Rgba8Image& unshadowed, int x, int y) {
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= static_cast<int>(shadowed.width) || py >= static_cast<int>(shadowed.height)) continue;
            const std::size_t i = 4 * (std::size_t(py) * shadowed.width + std::size_t(px));
            bool darker = true;
            for (int ch = 0; ch < 3; ++ch) darker = darker && int(unshadowed.pixels[i + ch]) - int(shadowed.pixels[i + ch]) > 4;
            if (darker) return true;
        }
    return false;
}

// Pixels that shadows darkened by more than 8 of 255 in every colour channel.
std::vector<bool> darkened(const app::Rgba8Image& shadowed, const app::Rgba8Image& unshadowed) {
    return test::darkenedPixels(shadowed, unshadowed, 8);
}

// The share of pixels darkened in either picture that are darkened in both, over rows from `firstRow`.
double overlap(const std::vector<bool>& a, const std::vector<bool>& b, std::uint32_t width, std::uint32_t firstRow) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = std::size_t{firstRow} * width; i < a.size(); ++i) both += a[i] && b[i], either += a[i] || b[i];
    return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

}  // namespace

// The file of soldiers seen along its length at 480x270, the shadow map 512 texels a side. Each soldier's
// shadow is looked for on the ground beside it, away from the sun (where its torso's shadow falls): with
// four cascades (a 256-texel square each) every soldier whose shadow the reference shows there (one map
// of 2048 texels over the whole view, sixteen times the texels) shows it too, in every cascade's
// stretch (a gap, a stretch no cascade owned, would leave its soldiers without). And the near half of
// the picture, where the shadows are large, is closer to the reference than one 512-texel map over the
// whole view draws it.
TEST_F(GpuTest, CascadedShadowsFallInEveryStretchAndSharpenTheNearOnes) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const FilePicture unshadowed = renderFile(*context, soldier, false, 1, 512);
    const FilePicture reference = renderFile(*context, soldier, true, 1, 2048);
    const FilePicture cascaded = renderFile(*context, soldier, true, 4, 512);
    const FilePicture single = renderFile(*context, soldier, true, 1, 512);
    const glm::vec3 light = render::lightDirection();
    const glm::vec3 away = glm::normalize(glm::vec3(-light.x, 0.0f, -light.z));
    const float torsoShadow = 1.2f / light.y * glm::length(glm::vec2(light.x, light.z));  // 1.2 m up, cast on the ground
    std::size_t inReference = 0, inCascaded = 0;
    std::set<int> stretches;
    for (const crowd::Character& c : fileOfSoldiers(soldier)) {
        const glm::vec3 ground = c.position + torsoShadow * away;
        const glm::vec4 clip = unshadowed.viewProjection * glm::vec4(ground, 1.0f);
        const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kWidth, kHeight);
        const int x = static_cast<int>(pixel.x), y = static_cast<int>(pixel.y);
        const bool referenceShadow = darkenedNear(reference.picture, unshadowed.picture, x, y);
        const bool cascadedShadow = darkenedNear(cascaded.picture, unshadowed.picture, x, y);
        const int stretch = render::cascadeHolding(cascaded.cascades, ground);
        std::printf("soldier %5.1f m ahead, shadow at pixel (%3d, %3d), cascade %d: reference %s, four cascades %s\n",
                    -c.position.z, x, y, stretch, referenceShadow ? "shadow" : "none", cascadedShadow ? "shadow" : "none");
        inReference += referenceShadow;
        if (referenceShadow) {
            EXPECT_TRUE(cascadedShadow) << "the soldier " << -c.position.z << " m ahead casts no shadow in cascade " << stretch;
            inCascaded += cascadedShadow;
            stretches.insert(stretch);
        }
    }
    EXPECT_GE(inReference, 16u) << "the reference shows most soldiers' shadows (the test looks in the right place)";
    EXPECT_GE(stretches.size(), 3u) << "the soldiers' shadows fall in three cascades' stretches (the fourth is past them)";
    const std::vector<bool> referenceMask = darkened(reference.picture, unshadowed.picture);
    const double nearCascaded = overlap(darkened(cascaded.picture, unshadowed.picture), referenceMask, kWidth, kHeight / 2);
    const double nearSingle = overlap(darkened(single.picture, unshadowed.picture), referenceMask, kWidth, kHeight / 2);
    std::printf("near half: overlap of the darkened pixels with the reference's %.3f with four cascades, %.3f with one map\n",
                nearCascaded, nearSingle);
    EXPECT_GT(nearCascaded, nearSingle + 0.05);
}

// The programs take --shadow-cascades 1 to 4: another count is refused in one line with status 1; two
// cascades with the hardware shadow raster and impostors casting (a rendering pass over the copied map
// per cascade, scissored), and four with the compute one, draw with validation silent, and the summary
// says how many.
TEST_F(GpuTest, ShadowCascadesFlagIsCheckedAndDrawsWithValidationSilent) {
    const char* deviceName = std::getenv("CROWD_TEST_DEVICE");
    const std::string deviceFlag = deviceName ? std::string(" --device '") + deviceName + "'" : "";
    const std::string render = CROWD_RENDER_BINARY, bench = CROWD_BENCH_BINARY;
    for (const std::string& program : {render, bench}) {
        for (const char* count : {"0", "5", "many"}) {
            const test::ProgramResult r = test::runProgram(program, std::string("--shadow-cascades ") + count + deviceFlag);
            EXPECT_EQ(r.exitCode, 1) << count << ": " << r.err;
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
            EXPECT_NE(r.err.find("--shadow-cascades"), std::string::npos) << r.err;
        }
    }
    const std::string small = "--count 64 --frames 2 --size 96x64 --impostors on --impostor-threshold 40 --validation --out /dev/null";
    const test::ProgramResult hardware =
        test::runProgram(render, small + " --shadow-cascades 2 --shadow-raster hardware" + deviceFlag);
    EXPECT_EQ(hardware.exitCode, 0) << hardware.err;
    EXPECT_TRUE(hardware.err.empty()) << hardware.err;
    EXPECT_NE(hardware.out.find("shadows on (hardware raster, 2 cascades)"), std::string::npos) << hardware.out;
    const test::ProgramResult compute = test::runProgram(render, small + " --shadow-cascades 4" + deviceFlag);
    EXPECT_EQ(compute.exitCode, 0) << compute.err;
    EXPECT_TRUE(compute.err.empty()) << compute.err;
    EXPECT_NE(compute.out.find("shadows on (compute raster, 4 cascades)"), std::string::npos) << compute.out;
}

// Renderer::setShadowCascades between frames draws what a renderer made with that many cascades draws,
// and back; a count out of range is refused with the renderer unchanged.
TEST_F(GpuTest, ShadowCascadesSetBetweenFramesDrawWhatARendererMadeWithThemDraws) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Crowd crowd(soldier, fileOfSoldiers(soldier));
    auto optionsWith = [](std::uint32_t cascades) {
        test::RendererOptions options;
        options.size = {160, 90};
        options.method = skin::Method::Compute;
        options.shadowMapSize = 512;
        options.shadowCascades = cascades;
        return options;
    };
    auto frame = [](test::TestRenderer& renderer) {
        renderer.camera.eye = {-1.5f, 6.0f, 2.0f};
        renderer.camera.target = {0.5f, 0.0f, -25.0f};
        renderer.renderFrame(0.5);
        return renderer.readback();
    };
    test::TestRenderer madeWithFour(*device, crowd, optionsWith(4));
    const app::Rgba8Image four = frame(madeWithFour);
    test::TestRenderer switched(*device, crowd, optionsWith(1));
    const app::Rgba8Image one = frame(switched);
    switched.finish();
    switched.library().setShadowCascades(4);
    EXPECT_EQ(switched.library().settings().shadowCascades, 4u);
    EXPECT_EQ(frame(switched).pixels, four.pixels);
    switched.finish();
    EXPECT_THROW(switched.library().setShadowCascades(5), crowdgpu::Error);
    EXPECT_EQ(switched.library().settings().shadowCascades, 4u);
    switched.library().setShadowCascades(1);
    EXPECT_EQ(frame(switched).pixels, one.pixels);
    EXPECT_NE(one.pixels, four.pixels) << "the cascades change the picture";
}
