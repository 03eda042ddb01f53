// Culling and levels of detail: the CPU reference against hand-computed cases, the GPU pass against
// the CPU reference along a camera path, and pictures that culling must not change.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "crowd/cull_reference.h"
#include "app/crowd_renderer.h"
#include "model/procedural_models.h"
#include "app/camera_path.h"
#include "support/gpu_test.h"

namespace {

const glm::vec4 kLod{150.0f, 50.0f, 0.1f, 0.0f};  // thresholds 150 and 50 px, 10 % hysteresis

}  // namespace

TEST(CullReference, SphereTouchingOrOnAPlaneIsKeptAndOneJustOutsideIsCulled) {
    // Six planes of the box 0 <= x, y, z <= 10, normals inside.
    const glm::vec4 planes[6] = {{1, 0, 0, 0}, {-1, 0, 0, 10}, {0, 1, 0, 0}, {0, -1, 0, 10}, {0, 0, 1, 0}, {0, 0, -1, 10}};
    EXPECT_TRUE(crowd::sphereInFrustum(planes, {5, 5, 5, 1}));
    EXPECT_TRUE(crowd::sphereInFrustum(planes, {0, 5, 5, 0}));     // a point exactly on a plane
    EXPECT_TRUE(crowd::sphereInFrustum(planes, {-1, 5, 5, 1}));    // touching from outside
    EXPECT_FALSE(crowd::sphereInFrustum(planes, {-1.01f, 5, 5, 1}));
    EXPECT_FALSE(crowd::sphereInFrustum(planes, {5, 5, 11.5f, 1}));
}

TEST(CullReference, FrustumPlanesOfACameraKeepWhatIsInFrontAndCullWhatIsBehind) {
    render::Camera camera;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    const std::array<glm::vec4, 6> planes = crowd::frustumPlanes(camera.viewProjection(1.0f));
    for (const glm::vec4& p : planes) EXPECT_NEAR(glm::length(glm::vec3(p)), 1.0f, 1e-5f);
    EXPECT_TRUE(crowd::sphereInFrustum(planes.data(), {0, 0, 0, 0.5f}));
    EXPECT_FALSE(crowd::sphereInFrustum(planes.data(), {0, 0, 20, 0.5f}));   // behind the camera
    EXPECT_FALSE(crowd::sphereInFrustum(planes.data(), {30, 0, 0, 0.5f}));   // far to the side
    EXPECT_FALSE(crowd::sphereInFrustum(planes.data(), {0, 0, -2000, 1.0f}));  // beyond the far plane
}

TEST(CullReference, LevelFollowsProjectedSizeWithHysteresis) {
    // No previous level: the plain thresholds.
    EXPECT_EQ(crowd::chooseLod(151.0f, 0, kLod), 0u);
    EXPECT_EQ(crowd::chooseLod(149.0f, 0, kLod), 1u);
    EXPECT_EQ(crowd::chooseLod(49.0f, 0, kLod), 2u);
    // At LOD 1 (state 2): finer only past 150 x 1.1 = 165, coarser only below 50 x 0.9 = 45.
    EXPECT_EQ(crowd::chooseLod(160.0f, 2, kLod), 1u);
    EXPECT_EQ(crowd::chooseLod(166.0f, 2, kLod), 0u);
    EXPECT_EQ(crowd::chooseLod(46.0f, 2, kLod), 1u);
    EXPECT_EQ(crowd::chooseLod(44.0f, 2, kLod), 2u);
    // At LOD 0 (state 1): coarser only below 150 x 0.9 = 135; a jump far down goes straight to LOD 2.
    EXPECT_EQ(crowd::chooseLod(136.0f, 1, kLod), 0u);
    EXPECT_EQ(crowd::chooseLod(134.0f, 1, kLod), 1u);
    EXPECT_EQ(crowd::chooseLod(10.0f, 1, kLod), 2u);
    // At LOD 2 (state 3): finer only past 55.
    EXPECT_EQ(crowd::chooseLod(54.0f, 3, kLod), 2u);
    EXPECT_EQ(crowd::chooseLod(56.0f, 3, kLod), 1u);
}

TEST(CullReference, ProjectedDiameterHalvesWithTwiceTheDistance) {
    const glm::vec4 camera(0, 0, 0, 500.0f);
    EXPECT_FLOAT_EQ(crowd::projectedDiameter({0, 0, 10, 1}, camera), 100.0f);
    EXPECT_FLOAT_EQ(crowd::projectedDiameter({0, 0, 20, 1}, camera), 50.0f);
    EXPECT_GT(crowd::projectedDiameter({0, 0, 0.5f, 1}, camera), 1e30f);  // the camera is inside
}

namespace {

using test::GpuTest;

crowd::Crowd gridCrowd(const model::SkinnedModel& model, std::uint32_t count) {
    app::SceneOptions scene;
    scene.count = count;
    return crowd::Crowd(model, test::buildCharacters(model, scene));
}

std::vector<std::uint32_t> readLodState(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.drawLists().lodState());
    std::vector<std::uint32_t> state(renderer.buffers().characterCount());
    std::memcpy(state.data(), bytes.data(), state.size() * 4);
    return state;
}

// How close a character is to a decision: the smallest relative distance of its sphere to a plane
// or of its projected size to a (hysteresis-scaled) threshold. Float rounding may flip only these.
float decisionMargin(const gpu::CullUniforms& u, const gpu::CharacterRecord& c, const gpu::ModelRecord& m) {
    const glm::vec4 sphere = crowd::worldSphere(c, m);
    float margin = 1e30f;
    for (const glm::vec4& p : u.planes)
        margin = std::min(margin, std::abs(glm::dot(glm::vec3(p), glm::vec3(sphere)) + p.w + sphere.w) /
                                      std::max(sphere.w, 1e-3f));
    const float size = crowd::projectedDiameter(sphere, u.camera);
    for (float t : {u.lod.x, u.lod.y}) {
        for (float s : {1.0f, 1.0f - u.lod.z, 1.0f + u.lod.z}) {
            margin = std::min(margin, std::abs(size - t * s) / (t * s));
        }
    }
    return margin;
}

}  // namespace

TEST_F(GpuTest, GpuCullingAndLodChoicesEqualTheCpuReferenceAlongACameraPath) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Crowd crowd = gridCrowd(soldier, 900);
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.cull.lodThresholds[0] = 30.0f;  // sizes a 90-pixel image shows, so every level is used
    options.cull.lodThresholds[1] = 12.0f;
    test::TestRenderer renderer(*device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    std::set<std::uint32_t> visibleCounts, levelsUsed, coarsestCounts;
    for (float seconds : {0.0f, 3.0f, 6.0f, 9.0f, 12.0f, 15.0f, 18.0f, 20.0f}) {
        const std::vector<std::uint32_t> before = readLodState(*context, renderer);
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, shape, 160.0f / 90.0f, seconds);
        renderer.renderFrame(seconds);
        renderer.finish();
        const gpu::CullUniforms uniforms = renderer.cullUniforms();
        std::vector<std::uint32_t> cpuState = before;
        const crowd::VisibleLists expected =
            crowd::cullOnCpu(uniforms, renderer.buffers().records(), renderer.pool().models(), cpuState);
        const crowd::VisibleLists gpu = test::readVisibleLists(*context, renderer);
        const std::vector<std::uint32_t> gpuState = readLodState(*context, renderer);
        std::uint32_t visible = 0;
        for (std::size_t b = 0; b < expected.size(); ++b) {
            visible += static_cast<std::uint32_t>(gpu[b].size());
            std::vector<std::uint32_t> differ;
            std::set_symmetric_difference(expected[b].begin(), expected[b].end(), gpu[b].begin(), gpu[b].end(),
                                          std::back_inserter(differ));
            for (std::uint32_t c : differ) {
                EXPECT_LT(decisionMargin(uniforms, renderer.buffers().records()[c], renderer.pool().models()[0]), 1e-4f)
                    << "character " << c << " at " << seconds << " s is in bucket " << b << " on one side only";
            }
        }
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            if (gpuState[c] == cpuState[c]) continue;
            EXPECT_LT(decisionMargin(uniforms, renderer.buffers().records()[c], renderer.pool().models()[0]), 1e-4f)
                << "character " << c << " level differs at " << seconds << " s";
        }
        visibleCounts.insert(visible);
        for (std::uint32_t l = 0; l < LOD_COUNT; ++l)
            if (!gpu[l].empty()) levelsUsed.insert(l);
        coarsestCounts.insert(static_cast<std::uint32_t>(gpu[2].size()));
    }
    // Not a trivial path: culling removes characters and the levels change along it.
    EXPECT_GT(visibleCounts.size(), 3u);
    EXPECT_LT(*visibleCounts.begin(), crowd.size());
    EXPECT_GE(levelsUsed.size(), 2u);
    EXPECT_GT(coarsestCounts.size(), 2u);
}

namespace {

app::Rgba8Image renderAt(const gpu::VulkanContext& context, crowd::Crowd crowd, const render::CullSettings& cull,
                            const app::Camera& camera, skin::Method method = skin::Method::Compute,
                            render::LodCounts* lods = nullptr) {
    test::RendererOptions options;
    options.size = {192, 108};
    options.method = method;
    options.cull = cull;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera = test::appCamera(camera);
    renderer.renderFrame(1.25f);
    app::Rgba8Image image = renderer.readback();
    if (lods) *lods = test::internalCounts(renderer.stats().back().lods);
    return image;
}

}  // namespace

TEST_F(GpuTest, CulledCrowdRendersTheSameImageAsTheUnculledOne) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Crowd crowd = gridCrowd(soldier, 256);
    const app::Camera camera =
        app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 192.0f / 108.0f, 8.0f);
    render::CullSettings culled, unculled, onCpu;
    unculled.mode = render::CullMode::Off;
    onCpu.mode = render::CullMode::Cpu;
    render::LodCounts withCulling, without;
    const app::Rgba8Image a = renderAt(*context, crowd, culled, camera, skin::Method::Compute, &withCulling);
    const app::Rgba8Image b = renderAt(*context, crowd, unculled, camera, skin::Method::Compute, &without);
    const app::Rgba8Image c = renderAt(*context, crowd, onCpu, camera);
    EXPECT_LT(withCulling.visible(), without.visible()) << "the camera must leave characters out of view";
    EXPECT_EQ(without.visible(), crowd.size());
    // Same characters at the same levels; only the draw order differs (equal-depth pixels at most).
    const double matching = test::fractionOfMatchingPixels(a, b, 2);
    if (matching < 0.999) {
        app::writePng(test::artifactPath("culled.png"), a);
        app::writePng(test::artifactPath("unculled.png"), b);
    }
    EXPECT_GE(matching, 0.999) << "images left in " << test::artifactPath("");
    EXPECT_GE(test::fractionOfMatchingPixels(a, c, 2), 0.999) << "CPU culling draws what GPU culling draws";
}

TEST_F(GpuTest, MixedCrowdRendersEachModelAsItsOwnCrowdDoes) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    const test::MixedCrowdMatch match = test::compareMixedCrowd(*device, soldier, horse, 1.0f, "soldier-horse");
    EXPECT_GT(match.firstModelPixels, 100u);
    EXPECT_GT(match.secondModelPixels, 100u);
    // Same characters, same math: only an edge pixel may round differently.
    EXPECT_GE(match.matchingFraction, 0.995) << "images left in " << test::artifactPath("");
    EXPECT_GE(match.firstModelMatching, 0.97);
    EXPECT_GE(match.secondModelMatching, 0.97);
}

TEST_F(GpuTest, GpuKeepsACharacterCentredOnAFrustumPlaneAndDropsOneJustOutside) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    render::Camera camera;
    camera.eye = {0.0f, 1.0f, 20.0f};
    camera.target = {0.0f, 1.0f, 0.0f};
    const float aspect = 1.5f;
    const glm::vec4 left = crowd::frustumPlanes(camera.viewProjection(aspect))[0];
    const glm::vec3 sphereCentre(soldier.poseSphere);
    const float radius = soldier.poseSphere.w;
    // A character placed by where its pose sphere's centre lands (heading 0, scale 1): at z = 0, the x
    // where the left plane's distance is d.
    auto placeAt = [&](float d) {
        crowd::Character c;
        const float z = 0.0f, y = sphereCentre.y;
        const float x = (d - left.w - left.y * y - left.z * z) / left.x;
        c.position = glm::vec3(x, 0.0f, z) - glm::vec3(sphereCentre.x, 0.0f, sphereCentre.z);
        return c;
    };
    crowd::Crowd crowd(soldier, {placeAt(0.0f), placeAt(-1.01f * radius), placeAt(-0.99f * radius)});
    test::RendererOptions options;
    options.size = {96, 64};
    options.method = skin::Method::Compute;
    options.shadows = false;  // the view alone decides (with shadows, casters outside it are kept)
    test::TestRenderer renderer(*device, crowd, options);
    renderer.camera = test::appCamera(camera);
    renderer.renderFrame(0.0f);
    renderer.finish();
    const std::map<std::uint32_t, test::DrawnCharacter> drawn = test::readDrawList(*context, renderer);
    EXPECT_EQ(drawn.count(0), 1u) << "centred on the plane: half of it is in view";
    EXPECT_EQ(drawn.count(1), 0u) << "its sphere wholly outside, by 1 % of the radius";
    EXPECT_EQ(drawn.count(2), 1u) << "its sphere just touching the view";
}
