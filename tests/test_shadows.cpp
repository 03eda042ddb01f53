// Shadows from the animated pose: the shadow lands on the ground away from the light, follows the
// limbs, and the cull pass keeps characters out of view whose shadows reach into it.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "crowd/cull_reference.h"
#include "app/crowd_renderer.h"
#include "render/shadow_map.h"
#include "support/gpu_test.h"

TEST(ShadowCasters, ACasterOutsideTheViewIsKeptOnlyWhenItsShadowCanReachIntoIt) {
    // The box 0 <= x, y, z <= 10; a sphere beyond x = 0, the light low in -x or +x.
    const glm::vec4 planes[6] = {{1, 0, 0, 0}, {-1, 0, 0, 10}, {0, 1, 0, 0}, {0, -1, 0, 10}, {0, 0, 1, 0}, {0, 0, -1, 10}};
    const glm::vec4 outside(-5, 5, 5, 1);
    EXPECT_FALSE(crowd::sphereInFrustum(planes, outside));
    // Light towards -x: the shadow falls towards +x, into the box.
    EXPECT_TRUE(crowd::casterInFrustum(planes, outside, glm::normalize(glm::vec3(-1, 0.3f, 0))));
    // Light towards +x: the shadow falls away from the box.
    EXPECT_FALSE(crowd::casterInFrustum(planes, outside, glm::normalize(glm::vec3(1, 0.3f, 0))));
}

namespace {

using test::GpuTest;

struct Shot {
    app::Rgba8Image image;
    glm::mat4 viewProjection;
};

// One soldier at the origin, seen from the front and above, at animation time `time`.
Shot renderSoldier(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, float time, bool shadows) {
    crowd::Character c;
    c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
    crowd::Crowd crowd(soldier, {c});
    test::RendererOptions options;
    options.size = {160, 120};
    options.method = skin::Method::Compute;
    options.shadows = shadows;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera.eye = {0.0f, 5.0f, 6.0f};
    renderer.camera.target = {0.0f, 0.5f, 0.0f};
    renderer.renderFrame(time);
    return {renderer.readback(), test::internalCamera(renderer.camera).viewProjection(160.0f / 120.0f)};
}

// Pixels that shadows darkened by more than 8 of 255 in every colour channel.
std::vector<bool> darkened(const app::Rgba8Image& on, const app::Rgba8Image& off) {
    std::vector<bool> mask(on.pixels.size() / 4);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        bool darker = true;
        for (int ch = 0; ch < 3; ++ch) darker = darker && int(off.pixels[4 * i + ch]) - int(on.pixels[4 * i + ch]) > 8;
        mask[i] = darker;
    }
    return mask;
}

glm::vec2 toPixel(const glm::mat4& viewProjection, const glm::vec3& world, int width, int height) {
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    return {(clip.x / clip.w * 0.5f + 0.5f) * width, (clip.y / clip.w * 0.5f + 0.5f) * height};
}

}  // namespace

TEST_F(GpuTest, ShadowDarkensTheGroundBesideTheCharacterAwayFromTheLight) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const Shot on = renderSoldier(*context, soldier, 0.2f, true);
    const Shot off = renderSoldier(*context, soldier, 0.2f, false);
    const std::vector<bool> mask = darkened(on.image, off.image);
    glm::vec2 centroid(0.0f);
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) centroid += glm::vec2(i % on.image.width, i / on.image.width), ++count;
    ASSERT_GT(count, 40u) << "a standing soldier's shadow covers some ground";
    centroid /= static_cast<float>(count);
    // On the ground a metre from the feet, away from the light (where the shadow must be) and towards it.
    const glm::vec3 l = render::lightDirection();
    const glm::vec3 away = -glm::normalize(glm::vec3(l.x, 0.0f, l.z));
    const glm::vec2 shadowSide = toPixel(on.viewProjection, away, on.image.width, on.image.height);
    const glm::vec2 lightSide = toPixel(on.viewProjection, -away, on.image.width, on.image.height);
    EXPECT_LT(glm::distance(centroid, shadowSide), glm::distance(centroid, lightSide))
        << "darkened pixels centre on (" << centroid.x << ", " << centroid.y << ")";
}

TEST_F(GpuTest, ShadowMovesWithTheAnimatedLimbs) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const std::vector<bool> early =
        darkened(renderSoldier(*context, soldier, 0.0f, true).image, renderSoldier(*context, soldier, 0.0f, false).image);
    const std::vector<bool> later =
        darkened(renderSoldier(*context, soldier, 0.3f, true).image, renderSoldier(*context, soldier, 0.3f, false).image);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < early.size(); ++i) differ += early[i] != later[i];
    EXPECT_GT(differ, 20u) << "a walking soldier's shadow changes shape within a third of a second";
}
