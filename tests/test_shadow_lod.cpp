// Shadows that cost what they show: casters drawn into the shadow map at a level from their size there
// (the GPU's choices equal the CPU reference's), culled against the map's volume, kept out of view when
// their shadow falls into it, impostors casting a quad facing the light, and a colour pass whose lit
// pixels do not change with the shadow's level of detail.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
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
    // Planes that hold everything, a shadow map of 10 texels per unit: a unit sphere is 20 texels across.
    gpu::CullUniforms u{};
    for (int i = 0; i < 6; ++i) u.planes[i] = u.lightPlanes[i] = glm::vec4(0, 0, 0, 1e6f);
    u.flags = glm::uvec4(1, 1, 1, 3);  // culling and LOD on
    u.limits.y = 1;                    // shadows on
    u.light = glm::vec4(0, 1, 0, 0);
    u.shadowFlags.x = 1;               // shadow LOD on
    u.shadow = glm::vec4(10.0f, 30.0f, 15.0f, 2.0f);
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
    // Outside the shadow map's volume: no shadow, in view or not.
    u.lightPlanes[0] = glm::vec4(1, 0, 0, -5);  // keeps x >= 5
    EXPECT_EQ(crowd::shadowState(sphere, 0, true, u) & SHADOW_CASTS_BIT, 0u);
    EXPECT_NE(crowd::shadowState(sphere, 0, true, u) & SHADOW_IN_VIEW_BIT, 0u);
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
    for (const glm::vec4* planes : {u.planes, u.lightPlanes})
        for (int i = 0; i < 6; ++i)
            margin = std::min(margin, std::abs(glm::dot(glm::vec3(planes[i]), glm::vec3(sphere)) + planes[i].w + sphere.w) /
                                          std::max(sphere.w, 1e-3f));
    const float size = crowd::projectedDiameter(sphere, u.camera);
    for (float t : {u.lod.x, u.lod.y, u.lod.w})
        for (float s : {1.0f, 1.0f - u.lod.z, 1.0f + u.lod.z}) margin = std::min(margin, std::abs(size - t * s) / (t * s));
    const float texels = 2.0f * sphere.w * u.shadow.x;
    for (float t : {u.shadow.y, u.shadow.z, u.shadow.w}) margin = std::min(margin, std::abs(texels - t) / t);
    return margin;
}

// Characters in one sorted list and not the other.
std::vector<std::uint32_t> differ(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    std::vector<std::uint32_t> result;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(result));
    return result;
}

}  // namespace

// A crowd of 900 flown over with impostors on, the shadow thresholds set each frame around the casters'
// size in the map (so the shadow level is coarser than the view's for the nearest): the GPU's shadow
// states, mesh casters per shadow level and casting impostors equal the CPU reference's, except for
// characters within 1e-4 of a decision (float rounding).
TEST_F(GpuTest, ShadowLevelsAndCastersEqualTheCpuReferenceAlongACameraPath) {
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
    test::TestRenderer renderer(*device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    const float radius = soldier.poseSphere.w;
    std::set<std::uint32_t> shadowLevelsUsed;
    std::uint32_t coarserThanView = 0, outOfViewCasters = 0, impostorCasters = 0, notCasting = 0;
    std::set<float> texelSizes;
    for (float seconds : {0.0f, 4.0f, 8.0f, 12.0f, 16.0f, 20.0f}) {
        const std::vector<std::uint32_t> before = readLodState(*context, renderer);
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, shape, 160.0f / 90.0f, seconds);
        renderer.renderFrame(seconds);
        renderer.finish();
        const gpu::CullUniforms uniforms = renderer.cullUniforms();
        texelSizes.insert(2.0f * radius * uniforms.shadow.x);
        std::vector<std::uint32_t> cpuState = before;
        std::vector<std::uint32_t> cpuImpostors;
        crowd::ShadowLists expected;
        const crowd::VisibleLists expectedVisible = crowd::cullOnCpu(uniforms, renderer.buffers().records(),
                                                                     renderer.pool().models(), cpuState, &cpuImpostors,
                                                                     nullptr, &expected);
        const crowd::ShadowLists gpu = test::readShadowLists(*context, renderer);
        const crowd::VisibleLists gpuVisible = test::readVisibleLists(*context, renderer);
        const gpu::ModelRecord& model = renderer.pool().models()[0];
        auto expectNearDecision = [&](std::uint32_t c, const char* what) {
            EXPECT_LT(decisionMargin(uniforms, renderer.buffers().records()[c], model), 1e-4f)
                << "character " << c << " at " << seconds << " s: " << what << " differs";
        };
        for (std::size_t b = 0; b < expected.casters.size(); ++b) {
            for (std::uint32_t c : differ(expected.casters[b], gpu.casters[b])) expectNearDecision(c, "its shadow level");
            for (std::uint32_t c : differ(expectedVisible[b], gpuVisible[b])) expectNearDecision(c, "its skinned level");
            if (!gpu.casters[b].empty()) shadowLevelsUsed.insert(static_cast<std::uint32_t>(b % LOD_COUNT));
        }
        for (std::uint32_t c : differ(expected.impostors, gpu.impostors)) expectNearDecision(c, "its impostor shadow");
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            if (gpu.states[c] != expected.states[c]) expectNearDecision(c, "its shadow state");
            const std::uint32_t state = gpu.states[c];
            const std::uint32_t viewLevel = std::max(cpuState[c], 1u) - 1u;
            if (!(state & SHADOW_CASTS_BIT)) {
                ++notCasting;
                continue;
            }
            if (!(state & SHADOW_IN_VIEW_BIT)) ++outOfViewCasters;
            if ((state & SHADOW_LEVEL_MASK) > viewLevel) ++coarserThanView;

            if ((state & SHADOW_LEVEL_MASK) == IMPOSTOR_LEVEL) ++impostorCasters;
        }
    }
    // Not a trivial path: the shadow level is coarser than the view's for some, casters out of view are
    // kept, impostors cast, and some characters cast nothing.
    std::printf("casters coarser than in view %u, out of view %u, impostors %u; not casting %u; %.1f to %.1f texels\n",
                coarserThanView, outOfViewCasters, impostorCasters, notCasting, *texelSizes.begin(), *texelSizes.rbegin());
    EXPECT_GE(shadowLevelsUsed.size(), 2u);
    EXPECT_GT(coarserThanView, 0u);
    EXPECT_GT(outOfViewCasters, 0u);
    EXPECT_GT(impostorCasters, 0u);
    EXPECT_GT(notCasting, 0u);
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
