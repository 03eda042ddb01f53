// Shadows that cost what they show: casters drawn into the shadow map at a level from their size there
// (the GPU's choices equal the CPU reference's), culled against the map's volume, kept out of view when
// their shadow falls into it, impostors casting a quad facing the light, and a colour pass whose lit
// pixels do not change with the shadow's level of detail.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <bit>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "app/crowd_app.h"
#include "app/crowd_renderer.h"
#include "crowd/cull_reference.h"
#include "render/shadow_map.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr float kDegree = 3.14159265f / 180.0f;

TEST(ShadowState, LevelFollowsTexelSizeNeverFinerThanTheViewAndTinyCastersAreDropped) {
    // Planes that hold everything, one cascade of 10 texels per unit: a unit sphere is 20 texels across.
    gpu::CullUniforms u{};
    for (int i = 0; i < 6; ++i) u.planes[i] = u.cascadePlanes[i] = glm::vec4(0, 0, 0, 1e6f);
    u.shadowFlags.z = 1;
    u.cascadeTexels.x = 10.0f;
    u.flags = glm::uvec4(1, 1, 1, 3);  // culling and LOD on
    u.limits.y = 1;                    // shadows on
    u.light = glm::vec4(0, 1, 0, 0);
    u.shadowFlags.x = 1;               // shadow LOD on
    u.shadow = glm::vec4(0.0f, 30.0f, 15.0f, 2.0f);
    const glm::vec4 sphere(0, 1, 0, 1);
    auto level = [&](std::uint32_t state) { return state & SHADOW_LEVEL_MASK; };
    EXPECT_EQ(level(crowd::shadowState(sphere, 0, true, u)), 1u);  // 20 texels: under 30, over 15
    EXPECT_EQ(level(crowd::shadowState(sphere, 2, true, u)), 2u);  // never finer than in view
    EXPECT_EQ(level(crowd::shadowState(sphere, IMPOSTOR_LEVEL, true, u)), IMPOSTOR_LEVEL);
    EXPECT_EQ(level(crowd::shadowState(glm::vec4(0, 1, 0, 0.5f), 0, true, u)), 2u);  // 10 texels
    EXPECT_NE(crowd::shadowState(sphere, 0, true, u) & SHADOW_CASTS_BIT, 0u);
    EXPECT_EQ(crowd::shadowState(glm::vec4(0, 1, 0, 0.09f), 0, true, u) & SHADOW_CASTS_BIT, 0u);  // 1.8 texels
    u.shadowFlags.x = 0;  // shadow LOD off: the view's level, and every caster drawn
    EXPECT_EQ(level(crowd::shadowState(sphere, 0, true, u)), 0u);
    EXPECT_NE(crowd::shadowState(glm::vec4(0, 1, 0, 0.09f), 0, true, u) & SHADOW_CASTS_BIT, 0u);
    EXPECT_EQ(crowd::shadowState(sphere, 0, true, u) >> SHADOW_CASCADE_SHIFT, 1u);  // cast in cascade 0
    // Outside the shadow map's volume: no shadow, in view or not.
    u.cascadePlanes[0] = glm::vec4(1, 0, 0, -5);  // keeps x >= 5
    EXPECT_EQ(crowd::shadowState(sphere, 0, true, u) & SHADOW_CASTS_BIT, 0u);
    EXPECT_NE(crowd::shadowState(sphere, 0, true, u) & SHADOW_IN_VIEW_BIT, 0u);
}

// Two cascades: a caster is drawn in each whose volume its sphere reaches, at a level from the finest of
// those (the first: cascades run from near to far), and casts nothing outside them all.
TEST(ShadowState, CascadesACasterReachesAndTheFinestOfThemSetsItsLevel) {
    gpu::CullUniforms u{};
    for (int i = 0; i < 6; ++i) u.planes[i] = u.cascadePlanes[i] = u.cascadePlanes[6 + i] = glm::vec4(0, 0, 0, 1e6f);
    u.cascadePlanes[0] = glm::vec4(-1, 0, 0, 0);  // cascade 0 keeps x <= 0
    u.cascadePlanes[6] = glm::vec4(1, 0, 0, 0);   // cascade 1 keeps x >= 0
    u.shadowFlags = glm::uvec4(1, 0, 2, 0);       // shadow LOD on, two cascades
    u.cascadeTexels = glm::vec4(40.0f, 10.0f, 0.0f, 0.0f);
    u.flags = glm::uvec4(1, 1, 1, 3);
    u.limits.y = 1;
    u.light = glm::vec4(0, 1, 0, 0);
    u.shadow = glm::vec4(0.0f, 30.0f, 15.0f, 2.0f);
    auto cascades = [&](const glm::vec4& sphere) { return crowd::shadowState(sphere, 0, true, u) >> SHADOW_CASCADE_SHIFT; };
    auto level = [&](const glm::vec4& sphere) { return crowd::shadowState(sphere, 0, true, u) & SHADOW_LEVEL_MASK; };
    EXPECT_EQ(cascades(glm::vec4(-3, 1, 0, 1)), 1u);  // cascade 0 only: 80 texels, LOD 0
    EXPECT_EQ(level(glm::vec4(-3, 1, 0, 1)), 0u);
    EXPECT_EQ(cascades(glm::vec4(3, 1, 0, 1)), 2u);   // cascade 1 only: 20 texels, LOD 1
    EXPECT_EQ(level(glm::vec4(3, 1, 0, 1)), 1u);
    EXPECT_EQ(cascades(glm::vec4(0.5f, 1, 0, 1)), 3u);  // across the split: both, at cascade 0's level
    EXPECT_EQ(level(glm::vec4(0.5f, 1, 0, 1)), 0u);
    u.cascadePlanes[6] = glm::vec4(1, 0, 0, -10);  // cascade 1 now keeps x >= 10: a gap between them
    EXPECT_EQ(crowd::shadowState(glm::vec4(5, 1, 0, 1), 0, true, u) & SHADOW_CASTS_BIT, 0u);
    u.flags.y = 0;  // culling off: every caster in every cascade
    EXPECT_EQ(cascades(glm::vec4(5, 1, 0, 1)), 3u);
}

std::vector<std::uint32_t> readLodState(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.drawLists().lodState());
    std::vector<std::uint32_t> state(renderer.buffers().characterCount());
    std::memcpy(state.data(), bytes.data(), state.size() * 4);
    return state;
}

// How close a character is to a decision: the smallest relative distance of its sphere to a plane (the
// view's or the shadow map's), of its projected size to a view threshold or of its size in texels to a
// shadow threshold. Float rounding may flip only these.
float decisionMargin(const gpu::CullUniforms& u, const gpu::CharacterRecord& c, const gpu::ModelRecord& m) {
    const glm::vec4 sphere = crowd::worldSphere(c, m);
    float margin = 1e30f;
    std::vector<const glm::vec4*> volumes = {u.planes};
    for (std::uint32_t k = 0; k < u.shadowFlags.z; ++k) volumes.push_back(u.cascadePlanes + 6 * k);
    for (const glm::vec4* planes : volumes)
        for (int i = 0; i < 6; ++i)
            margin = std::min(margin, std::abs(glm::dot(glm::vec3(planes[i]), glm::vec3(sphere)) + planes[i].w + sphere.w) /
                                          std::max(sphere.w, 1e-3f));
    const float size = crowd::projectedDiameter(sphere, u.camera);
    for (float t : {u.lod.x, u.lod.y, u.lod.w})
        for (float s : {1.0f, 1.0f - u.lod.z, 1.0f + u.lod.z}) margin = std::min(margin, std::abs(size - t * s) / (t * s));
    for (std::uint32_t k = 0; k < u.shadowFlags.z; ++k) {
        const float texels = 2.0f * sphere.w * u.cascadeTexels[static_cast<int>(k)];
        for (float t : {u.shadow.y, u.shadow.z, u.shadow.w}) margin = std::min(margin, std::abs(texels - t) / t);
    }
    return margin;
}

}  // namespace

// A crowd of 900 flown over with impostors on, the shadow thresholds set each frame around the casters'
// size in the map (so the shadow level is coarser than the view's for the nearest): the GPU's shadow
// states, mesh casters per shadow level and casting impostors equal the CPU reference's, except for
// characters within 1e-4 of a decision (float rounding).
namespace {

struct PathCounts {
    std::set<std::uint32_t> shadowLevelsUsed;
    std::uint32_t coarserThanView = 0, outOfViewCasters = 0, impostorCasters = 0, notCasting = 0;
    std::set<std::uint32_t> cascadeSets;  // the casters' sets of cascades (state words' bits)
    std::set<float> texelSizes;
};

PathCounts compareShadowStatesAlongAPath(const app::HostDevice& device, const gpu::VulkanContext& context,
                                         std::uint32_t cascades) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 900;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.cull.lodThresholds[0] = 30.0f;  // sizes a 90-pixel image shows, so every level is used
    options.cull.lodThresholds[1] = 12.0f;
    options.cull.shadowLodThresholds[0] = 30.0f;  // as the library sets them: the view's, read in texels
    options.cull.shadowLodThresholds[1] = 12.0f;
    options.cull.impostors = true;
    options.cull.impostorThreshold = 11.0f;
    // A small map, so a caster is 11 to 16 texels across in it (the view's thresholds read in texels:
    // LOD 1 or 2 from the texels alone), as in a large scene's 2048-texel map.
    options.shadowMapSize = 240;
    options.shadowCascades = cascades;
    test::TestRenderer renderer(device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    const float radius = soldier.poseSphere.w;
    PathCounts n;
    for (float seconds : {0.0f, 4.0f, 8.0f, 12.0f, 16.0f, 20.0f}) {
        const std::vector<std::uint32_t> before = readLodState(context, renderer);
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, shape, 160.0f / 90.0f, seconds);
        renderer.renderFrame(seconds);
        renderer.finish();
        const gpu::CullUniforms uniforms = renderer.cullUniforms();
        n.texelSizes.insert(2.0f * radius * uniforms.cascadeTexels.x);
        std::vector<std::uint32_t> cpuState = before;
        std::vector<std::uint32_t> cpuImpostors;
        crowd::ShadowLists expected;
        const crowd::VisibleLists expectedVisible = crowd::cullOnCpu(uniforms, renderer.buffers().records(),
                                                                     renderer.pool().models(), cpuState, &cpuImpostors,
                                                                     nullptr, &expected);
        const crowd::ShadowLists gpu = test::readShadowLists(context, renderer);
        const crowd::VisibleLists gpuVisible = test::readVisibleLists(context, renderer);
        const gpu::ModelRecord& model = renderer.pool().models()[0];
        auto expectNearDecision = [&](std::uint32_t c, const char* what) {
            EXPECT_LT(decisionMargin(uniforms, renderer.buffers().records()[c], model), 1e-4f)
                << "character " << c << " at " << seconds << " s: " << what << " differs";
        };
        for (std::size_t b = 0; b < expected.casters.size(); ++b) {
            for (std::uint32_t c : test::differ(expected.casters[b], gpu.casters[b])) expectNearDecision(c, "its shadow level");
            for (std::uint32_t c : test::differ(expectedVisible[b], gpuVisible[b])) expectNearDecision(c, "its skinned level");
            if (!gpu.casters[b].empty()) n.shadowLevelsUsed.insert(static_cast<std::uint32_t>(b % LOD_COUNT));
        }
        for (std::uint32_t c : test::differ(expected.impostors, gpu.impostors)) expectNearDecision(c, "its impostor shadow");
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            if (gpu.states[c] != expected.states[c]) expectNearDecision(c, "its shadow state");
            const std::uint32_t state = gpu.states[c];
            const std::uint32_t viewLevel = std::max(cpuState[c], 1u) - 1u;
            if (!(state & SHADOW_CASTS_BIT)) {
                ++n.notCasting;
                continue;
            }
            n.cascadeSets.insert((state >> SHADOW_CASCADE_SHIFT) & 15u);
            if (!(state & SHADOW_IN_VIEW_BIT)) ++n.outOfViewCasters;
            if ((state & SHADOW_LEVEL_MASK) > viewLevel) ++n.coarserThanView;

            if ((state & SHADOW_LEVEL_MASK) == IMPOSTOR_LEVEL) ++n.impostorCasters;
        }
    }
    return n;
}

}  // namespace

TEST_F(GpuTest, ShadowLevelsAndCastersEqualTheCpuReferenceAlongACameraPath) {
    const PathCounts n = compareShadowStatesAlongAPath(*device, *context, 1);
    // Not a trivial path: the shadow level is coarser than the view's for some, casters out of view are
    // kept, impostors cast, and some characters cast nothing.
    std::printf("casters coarser than in view %u, out of view %u, impostors %u; not casting %u; %.1f to %.1f texels\n",
                n.coarserThanView, n.outOfViewCasters, n.impostorCasters, n.notCasting, *n.texelSizes.begin(),
                *n.texelSizes.rbegin());
    EXPECT_GE(n.shadowLevelsUsed.size(), 2u);
    EXPECT_GT(n.coarserThanView, 0u);
    EXPECT_GT(n.outOfViewCasters, 0u);
    EXPECT_GT(n.impostorCasters, 0u);
    EXPECT_GT(n.notCasting, 0u);
}

// The same with four cascades: each caster's cascades (the bits the compute shadow raster draws it in)
// and its level from the finest of them equal the CPU's too; casters fall in several cascades, some in
// two at once (across a split).
TEST_F(GpuTest, ShadowCascadesOfEachCasterEqualTheCpuReferenceAlongACameraPath) {
    const PathCounts n = compareShadowStatesAlongAPath(*device, *context, 4);
    std::set<std::uint32_t> cascadesUsed;
    bool straddles = false;
    for (std::uint32_t set : n.cascadeSets) {
        for (std::uint32_t k = 0; k < 4; ++k)
            if (set & (1u << k)) cascadesUsed.insert(k);
        straddles = straddles || std::popcount(set) > 1;
    }
    std::printf("cascade sets of casters: %zu, cascades used %zu\n", n.cascadeSets.size(), cascadesUsed.size());
    EXPECT_FALSE(n.cascadeSets.count(0u)) << "a caster in no cascade";
    EXPECT_GE(cascadesUsed.size(), 3u);
    EXPECT_TRUE(straddles);
    EXPECT_GT(n.outOfViewCasters, 0u);
    EXPECT_GT(n.impostorCasters, 0u);
}

namespace {

// Pixels of `on` darker than `off` by more than `by` of 255 in every colour channel.
std::vector<bool> darkened(const app::Rgba8Image& on, const app::Rgba8Image& off, int by) {
    std::vector<bool> mask(on.pixels.size() / 4);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        bool darker = true;
        for (int ch = 0; ch < 3; ++ch) darker = darker && int(off.pixels[4 * i + ch]) - int(on.pixels[4 * i + ch]) > by;
        mask[i] = darker;
    }
    return mask;
}

std::size_t count(const std::vector<bool>& mask) { return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), true)); }

// One walking soldier at `position`, seen from nearly straight above the origin (160x120).
struct Shot {
    app::Rgba8Image image;
    std::uint32_t shadowState = 0;
};
Shot renderOne(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, const glm::vec3& position,
               bool shadows) {
    crowd::Character c;
    c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
    c.position = position;
    crowd::Crowd crowd(soldier, {c});
    test::RendererOptions options;
    options.size = {160, 120};
    options.method = skin::Method::Compute;
    options.shadows = shadows;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera.eye = {0.0f, 6.0f, 0.5f};
    renderer.camera.target = {0.0f, 0.0f, 0.0f};
    renderer.renderFrame(0.3f);
    renderer.finish();
    return {renderer.readback(), test::readShadowLists(context, renderer).states[0]};
}

}  // namespace

// A soldier just outside the view on the light's side casts its shadow into it (and the colour pass
// draws nothing else of it: every pixel that changes gets darker); the same soldier as far out on the
// other side casts nothing, its shadow falling away from the view.
TEST_F(GpuTest, ACasterOutsideTheViewStillCastsIntoIt) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const glm::vec3 l = render::lightDirection();
    const glm::vec3 towardsLight = glm::normalize(glm::vec3(l.x, 0.0f, l.z));
    app::Camera camera;
    camera.eye = {0.0f, 6.0f, 0.5f};
    camera.target = {0.0f, 0.0f, 0.0f};
    const std::array<glm::vec4, 6> planes = crowd::frustumPlanes(test::internalCamera(camera).viewProjection(160.0f / 120.0f));
    // The nearest distance along the light's side at which the pose sphere is out of view, plus 10 cm.
    auto outOfView = [&](const glm::vec3& direction) {
        for (float d = 0.5f; d < 20.0f; d += 0.05f) {
            const glm::vec4 sphere(d * direction + glm::vec3(soldier.poseSphere), soldier.poseSphere.w);
            if (!crowd::sphereInFrustum(planes.data(), sphere)) return (d + 0.1f) * direction;
        }
        return glm::vec3(20.0f) * direction;
    };
    for (const float side : {1.0f, -1.0f}) {
        const glm::vec3 position = outOfView(side * towardsLight);
        const Shot on = renderOne(*context, soldier, position, true);
        const Shot off = renderOne(*context, soldier, position, false);
        EXPECT_EQ(on.shadowState & SHADOW_IN_VIEW_BIT, 0u);
        std::size_t brighterOrOtherwise = 0;
        for (std::size_t i = 0; i < on.image.pixels.size() / 4; ++i) {
            bool darker = true;
            for (int ch = 0; ch < 3; ++ch) darker = darker && on.image.pixels[4 * i + ch] <= off.image.pixels[4 * i + ch];
            brighterOrOtherwise += darker ? 0 : 1;
        }
        const std::size_t shadowPixels = count(darkened(on.image, off.image, 8));
        EXPECT_EQ(brighterOrOtherwise, 0u) << "the colour pass draws nothing of a character out of view";
        if (side > 0.0f) {
            EXPECT_NE(on.shadowState & SHADOW_CASTS_BIT, 0u);
            EXPECT_GT(shadowPixels, 20u) << "the shadow of a soldier " << glm::length(position) << " m out falls in view";
        } else {
            EXPECT_EQ(on.shadowState & SHADOW_CASTS_BIT, 0u);
            EXPECT_EQ(shadowPixels, 0u);
        }
    }
}

namespace {

// Six soldiers in a row along x, each with its own heading and phase, tinted `tint`.
std::vector<crowd::Character> row(const model::SkinnedModel& soldier, float tint) {
    const float headings[6] = {0.0f, 1.0f, 2.2f, 3.5f, 4.4f, 5.6f};
    std::vector<crowd::Character> characters;
    for (int i = 0; i < 6; ++i) {
        crowd::Character c;
        c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
        c.timeOffset = 0.17f * static_cast<float>(i);
        c.position = glm::vec3(2.5f * (static_cast<float>(i) - 2.5f), 0.0f, 0.0f);
        c.heading = headings[i];
        c.tint = glm::vec3(tint);
        characters.push_back(c);
    }
    return characters;
}

// A camera 35 degrees above the row's middle, at the distance where a soldier's pose sphere is 31 px
// across in a 320x120 image: just under the 32 px switch to impostors.
app::Camera switchCamera(const model::SkinnedModel& soldier) {
    render::Camera camera;
    const float focal = 120.0f / (2.0f * std::tan(0.5f * camera.verticalFov));
    const float distance = 2.0f * soldier.poseSphere.w * focal / 31.0f;
    camera.target = glm::vec3(0.0f, glm::vec3(soldier.poseSphere).y, 0.0f);
    camera.eye = camera.target + distance * glm::vec3(0.0f, std::sin(35.0f * kDegree), std::cos(35.0f * kDegree));
    camera.nearPlane = 0.5f;
    camera.farPlane = 4.0f * distance;
    return test::appCamera(camera);
}

// The row as meshes or impostors, with shadows on or off.
app::Rgba8Image renderRow(test::TestRenderer& renderer, const app::Camera& camera, bool impostors, bool shadows) {
    render::CullSettings cull = renderer.cull();
    cull.impostors = impostors;
    renderer.setCull(cull);
    renderer.setShadows(shadows);
    renderer.camera = camera;
    renderer.renderFrame(0.7f);
    renderer.finish();
    const std::vector<app::FrameStats> stats = renderer.takeStats();
    EXPECT_EQ(impostors ? stats.back().lods.impostors : stats.back().lods.characters[2], 6u);
    if (shadows) {
        EXPECT_EQ(impostors ? stats.back().lods.shadowImpostors : stats.back().lods.shadowCharacters[2], 6u);
    }
    return renderer.readback();
}

}  // namespace

// At the switch size, the impostors' shadows (quads facing the light) fall where the meshes' shadows fall.
// Ground pixels only (a soldier's pixels are those its tint changes, in either picture): the shadows
// darken (by over 8/255) sets of ground pixels whose overlap is at least 60 % of their union, whose
// sizes are within 25 %, and each soldier's shadow's centroid is within 3 px of its mesh's (a soldier
// is 31 px across, its shadow about 50 ground pixels). The impostor's silhouette is its atlas
// cell's, up to half a view step (11.25 degrees) and half a frame away from the mesh's, hence the
// tolerance; a quad facing the camera, at the wrong place or with the wrong cell fails. The impostors
// do not shadow themselves: their pixels are as bright with shadows as without, within 3 %, as the
// meshes' are within 3 % (the quads are looked up a pose-sphere radius nearer the light).
TEST_F(GpuTest, AnImpostorCastsItsShadowWhereTheMeshCastsItsAtTheSwitchSize) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Crowd lit(soldier, row(soldier, 1.0f));
    crowd::Crowd dim(soldier, row(soldier, 0.6f));
    test::RendererOptions options;
    options.size = {320, 120};
    options.method = skin::Method::Compute;
    options.cull.impostors = true;  // bake once; renderRow switches levels
    options.cull.hysteresis = 0.0f;
    test::TestRenderer litRenderer(*context, lit, options);
    options.atlas = litRenderer.impostorAtlas();
    test::TestRenderer dimRenderer(*context, dim, options);
    const app::Camera camera = switchCamera(soldier);
    std::vector<bool> shadow[2];
    double brightness[2] = {};
    for (const bool impostors : {false, true}) {
        const app::Rgba8Image on = renderRow(litRenderer, camera, impostors, true);
        const app::Rgba8Image off = renderRow(litRenderer, camera, impostors, false);
        const app::Rgba8Image dimOff = renderRow(dimRenderer, camera, impostors, false);
        std::vector<bool>& mask = shadow[impostors ? 1 : 0];
        mask = darkened(on, off, 8);
        double sumOn = 0.0, sumOff = 0.0;
        for (std::size_t i = 0; i < mask.size(); ++i) {
            bool character = false;
            for (int ch = 0; ch < 3; ++ch) character = character || off.pixels[4 * i + ch] != dimOff.pixels[4 * i + ch];
            if (!character) continue;
            mask[i] = false;  // ground only
            for (int ch = 0; ch < 3; ++ch) sumOn += on.pixels[4 * i + ch], sumOff += off.pixels[4 * i + ch];
        }
        brightness[impostors ? 1 : 0] = sumOn / std::max(sumOff, 1.0);
        if (std::getenv("CROWD_KEEP_IMAGES")) {
            app::writePng(test::artifactPath(impostors ? "impostor-shadow.png" : "mesh-shadow.png"), on);
        }
    }
    // Character pixels of either picture are left out of both masks, so both compare the same ground. Each
    // shadow pixel belongs to the soldier whose feet are nearest across the image.
    const glm::mat4 viewProjection = test::internalCamera(camera).viewProjection(320.0f / 120.0f);
    float feet[6];
    for (int s = 0; s < 6; ++s) {
        const glm::vec4 clip = viewProjection * glm::vec4(2.5f * (static_cast<float>(s) - 2.5f), 0.0f, 0.0f, 1.0f);
        feet[s] = (clip.x / clip.w * 0.5f + 0.5f) * 320.0f;
    }
    std::size_t both = 0, either = 0, counts[2] = {};
    glm::vec2 centroid[2][6] = {};
    std::size_t soldierCounts[2][6] = {};
    for (std::size_t i = 0; i < shadow[0].size(); ++i) {
        const glm::vec2 pixel(static_cast<float>(i % 320), static_cast<float>(i / 320));
        int nearest = 0;
        for (int s = 1; s < 6; ++s)
            if (std::abs(pixel.x - feet[s]) < std::abs(pixel.x - feet[nearest])) nearest = s;
        for (int k = 0; k < 2; ++k)
            if (shadow[k][i]) centroid[k][nearest] += pixel, ++soldierCounts[k][nearest], ++counts[k];
        both += shadow[0][i] && shadow[1][i];
        either += shadow[0][i] || shadow[1][i];
    }
    float farthest = 0.0f;
    for (int s = 0; s < 6; ++s) {
        EXPECT_GT(soldierCounts[0][s], 10u) << "soldier " << s << " casts a shadow on the ground";
        EXPECT_GT(soldierCounts[1][s], 10u) << "soldier " << s << " as an impostor casts a shadow on the ground";
        const glm::vec2 mesh = centroid[0][s] / static_cast<float>(std::max<std::size_t>(soldierCounts[0][s], 1));
        const glm::vec2 impostor = centroid[1][s] / static_cast<float>(std::max<std::size_t>(soldierCounts[1][s], 1));
        farthest = std::max(farthest, glm::distance(mesh, impostor));
    }
    const double overlap = static_cast<double>(both) / static_cast<double>(std::max<std::size_t>(either, 1));
    std::printf("shadow pixels: mesh %zu, impostor %zu, overlap %.2f, a soldier's centroids at most %.2f px apart; "
                "brightness with shadows / without: mesh %.3f, impostor %.3f\n",
                counts[0], counts[1], overlap, farthest, brightness[0], brightness[1]);
    EXPECT_GE(overlap, 0.6);
    EXPECT_NEAR(static_cast<double>(counts[1]) / static_cast<double>(counts[0]), 1.0, 0.25);
    EXPECT_LT(farthest, 3.0f);
    EXPECT_NEAR(brightness[0], 1.0, 0.03);
    EXPECT_NEAR(brightness[1], 1.0, 0.03);
}

// The colour pass does not change its look with the shadow's level of detail: a crowd drawn with shadow
// LOD on and off (its shadows from LOD 2 where the view draws LOD 0 and 1) differs only in pixels that
// a shadow darkens in one of the two pictures; everywhere else (lit characters and ground) the pictures
// are identical. In shadow, at most 2 % of the image differs by over 24/255 in a channel (shadow edges).
TEST_F(GpuTest, ShadowLodChangesOnlyShadowedPixels) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 100;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {320, 180};
    options.method = skin::Method::Compute;
    options.shadowMapSize = 256;  // casters about 30 texels across (LOD 2), as in a large scene's 2048 map
    test::TestRenderer renderer(*device, crowd, options);
    // Low over the crowd's edge: the nearest soldiers at LOD 0 and 1 in view.
    const app::CrowdShape shape = test::shapeOf(crowd);
    renderer.camera.target = shape.center + glm::vec3(0.0f, 1.0f, 0.0f);
    renderer.camera.eye = shape.center + glm::vec3(0.0f, 4.0f, shape.radius + 3.0f);
    app::Rgba8Image images[3];  // shadow LOD on, off, no shadows
    std::uint64_t shadowTriangles[2] = {};
    for (int k = 0; k < 3; ++k) {
        render::CullSettings cull = renderer.cull();
        cull.shadowLod = k == 0;
        renderer.setCull(cull);
        renderer.setShadows(k < 2);
        renderer.renderFrame(0.5f);
        renderer.finish();
        const std::vector<app::FrameStats> stats = renderer.takeStats();
        if (k < 2) shadowTriangles[k] = stats.back().lods.shadowTriangles[0] + stats.back().lods.shadowTriangles[1] +
                                        stats.back().lods.shadowTriangles[2];
        if (k == 0) {
            EXPECT_GT(stats.back().lods.characters[0] + stats.back().lods.characters[1], 0u) << "some finer in view";
        }
        images[k] = renderer.readback();
    }
    const std::vector<bool> shadowOn = darkened(images[0], images[2], 0);
    const std::vector<bool> shadowOff = darkened(images[1], images[2], 0);
    std::size_t changed = 0, changedOutsideShadow = 0, changedMuch = 0;
    for (std::size_t i = 0; i < shadowOn.size(); ++i) {
        int most = 0;
        for (int ch = 0; ch < 3; ++ch)
            most = std::max(most, std::abs(int(images[0].pixels[4 * i + ch]) - int(images[1].pixels[4 * i + ch])));
        if (most == 0) continue;
        ++changed;
        // A pixel any shadow reaches is darker in some channel than without shadows.
        bool shadowed = false;
        for (int ch = 0; ch < 3; ++ch)
            shadowed = shadowed || images[0].pixels[4 * i + ch] < images[2].pixels[4 * i + ch] ||
                       images[1].pixels[4 * i + ch] < images[2].pixels[4 * i + ch];
        changedOutsideShadow += shadowed ? 0 : 1;
        changedMuch += most > 24 ? 1 : 0;
    }
    const double muchFraction = static_cast<double>(changedMuch) / static_cast<double>(shadowOn.size());
    std::printf("shadow triangles %llu with shadow LOD, %llu without; %zu pixels differ, %.2f %% by over 24/255\n",
                static_cast<unsigned long long>(shadowTriangles[0]), static_cast<unsigned long long>(shadowTriangles[1]),
                changed, 100.0 * muchFraction);
    EXPECT_LT(shadowTriangles[0], shadowTriangles[1]);
    EXPECT_EQ(changedOutsideShadow, 0u);
    EXPECT_LE(muchFraction, 0.02);
    if (std::getenv("CROWD_KEEP_IMAGES")) {
        app::writePng(test::artifactPath("shadow-lod-on.png"), images[0]);
        app::writePng(test::artifactPath("shadow-lod-off.png"), images[1]);
    }
}
