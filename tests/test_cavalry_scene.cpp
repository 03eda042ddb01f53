// The cavalry scene (docs/cavalry.md): its crowd, riders marching with foot soldiers, drawn on the GPU,
// has its riders where the CPU puts them. The same crowd is drawn twice, once with the riders' model and
// once with the horse alone in its place (same layout, clips and motion: the mounted horse moves as the
// horse alone, test_cavalry.cpp): every pixel that differs must lie where the CPU projects a rider
// (its mesh skinned on the CPU and projected), and most of the riders' pixels must differ.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "crowdgpu/error.hpp"
#include "app/scene_presets.h"
#include "crowd/crowd.h"
#include "skin/cpu_skinning.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

glm::vec2 toPixel(const glm::mat4& viewProjection, const glm::vec3& world, int width, int height) {
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    return {(clip.x / clip.w * 0.5f + 0.5f) * width, (clip.y / clip.w * 0.5f + 0.5f) * height};
}

struct Frame {
    app::Rgba8Image image;
    glm::mat4 viewProjection;
};

constexpr std::uint32_t kWidth = 320, kHeight = 240;
constexpr double kTime = 5.0;  // a second standing, then four marching

Frame renderMarch(const gpu::VulkanContext& context, crowd::Crowd& crowd) {
    test::RendererOptions options;
    options.size = {kWidth, kHeight};
    options.method = skin::Method::Compute;
    options.shadows = false;  // the riders' shadows would differ too: only the riders themselves here
    // Full detail for both: the mounted model's coarser levels are simplified from the pair's mesh, so
    // its horse differs from the lone horse's at levels 1 and 2.
    options.cull.lod = false;
    test::TestRenderer renderer(context, crowd, options);
    // From the column's right, high up: its 2 x 8 ranks, 4 m along their march, fill the picture.
    renderer.camera.eye = {26.0f, 24.0f, 4.0f};
    renderer.camera.target = {0.0f, 0.5f, 4.0f};
    renderer.renderFrame(kTime);
    return {renderer.readback(), test::internalCamera(renderer.camera).viewProjection(float(kWidth) / kHeight)};
}

int channelDifference(const app::Rgba8Image& a, const app::Rgba8Image& b, std::size_t pixel) {
    int most = 0;
    for (int ch = 0; ch < 3; ++ch) most = std::max(most, std::abs(int(a.pixels[4 * pixel + ch]) - int(b.pixels[4 * pixel + ch])));
    return most;
}

}  // namespace

TEST_F(GpuTest, CavalrySceneDrawsItsRidersWhereTheCpuPutsThem) {
    const app::ScenePreset& preset = app::findScenePreset("cavalry");
    ASSERT_EQ(preset.behaviour, crowdgpu::Behaviour::March);
    const std::vector<std::pair<std::string, float>> entries = app::parseModelList(preset.models);
    ASSERT_EQ(entries.size(), 2u);
    ASSERT_EQ(entries[0].first, "cavalry");
    const model::SkinnedModel cavalry = test::loadModel("cavalry"), horse = test::loadModel("horse");
    const model::SkinnedModel second = test::loadModel(entries[1].first);

    crowd::LayoutOptions layout;
    layout.count = 16;
    layout.weights = {entries[0].second, entries[1].second};
    layout.formation = true;
    layout.depthRatio = preset.depthRatio;
    crowd::BehaviourSettings march;
    march.kind = crowd::Behaviour::March;
    const std::vector<const model::SkinnedModel*> mounted = {&cavalry, &second}, unmounted = {&horse, &second};
    const std::vector<crowd::Character> characters = crowd::gridLayout(mounted, layout);
    crowd::Crowd withRiders(mounted, characters, march), withoutRiders(unmounted, characters, march);
    const Frame riders = renderMarch(*context, withRiders);
    const Frame horses = renderMarch(*context, withoutRiders);

    // Where the CPU puts each rider: its triangles skinned on the CPU (the crowd's bones, the double-
    // precision reference) and rasterized into a coverage mask, widened by a pixel for edge rounding.
    withRiders.advanceTo(kTime);
    const auto horseJoints = static_cast<std::uint32_t>(horse.skeleton.jointCount());
    // 2: a pixel centre inside a rider's triangle; 1: within a pixel of one.
    std::vector<std::uint8_t> riderPixels(std::size_t(kWidth) * kHeight, 0);
    std::vector<gpu::BoneRows> bones(cavalry.skeleton.jointCount());
    std::uint32_t riderCount = 0;
    for (std::uint32_t c = 0; c < characters.size(); ++c) {
        if (characters[c].model != 0) continue;
        ++riderCount;
        withRiders.animateCharacter(c, kTime, bones);
        const std::vector<skin::CpuSkinnedVertex> skinned = skin::skinOnCpu(cavalry, bones);
        for (std::size_t t = 0; t + 2 < cavalry.indices.size(); t += 3) {
            const std::uint32_t* tri = &cavalry.indices[t];
            if (cavalry.vertices[tri[0]].joints.x < horseJoints) continue;  // the horse's
            glm::vec2 p[3];
            for (int k = 0; k < 3; ++k) p[k] = toPixel(riders.viewProjection, glm::vec3(skinned[tri[k]].position), kWidth, kHeight);
            // A prop the rider does not carry is collapsed to a point: no area, no pixel.
            if ((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x) == 0.0f) continue;
            const glm::vec2 lo = glm::floor(glm::min(p[0], glm::min(p[1], p[2]))) - 1.0f;
            const glm::vec2 hi = glm::ceil(glm::max(p[0], glm::max(p[1], p[2]))) + 1.0f;
            for (int y = std::max(0, int(lo.y)); y <= std::min(int(kHeight) - 1, int(hi.y)); ++y)
                for (int x = std::max(0, int(lo.x)); x <= std::min(int(kWidth) - 1, int(hi.x)); ++x) {
                    // Within a pixel of the triangle: distance to it at most 1 (inside counts 0).
                    const glm::vec2 q(x + 0.5f, y + 0.5f);
                    auto edge = [&](glm::vec2 a, glm::vec2 b) {
                        const glm::vec2 ab = b - a;
                        const float t01 = glm::clamp(glm::dot(q - a, ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
                        return glm::distance(q, a + t01 * ab);
                    };
                    const float c0 = (p[1].x - p[0].x) * (q.y - p[0].y) - (p[1].y - p[0].y) * (q.x - p[0].x);
                    const float c1 = (p[2].x - p[1].x) * (q.y - p[1].y) - (p[2].y - p[1].y) * (q.x - p[1].x);
                    const float c2 = (p[0].x - p[2].x) * (q.y - p[2].y) - (p[0].y - p[2].y) * (q.x - p[2].x);
                    const bool inside = (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
                    std::uint8_t& mark = riderPixels[std::size_t(y) * kWidth + x];
                    if (inside) mark = 2;
                    else if (std::min({edge(p[0], p[1]), edge(p[1], p[2]), edge(p[2], p[0])}) <= 1.0f) mark = std::max<std::uint8_t>(mark, 1);
                }
        }
    }
    ASSERT_GE(riderCount, 8u) << "the scene is mostly riders";

    // The pictures differ exactly where the riders are: no differing pixel farther than a pixel from the
    // CPU's riders, and at least 80 % of the pixels whose centre a rider covers differ (the rest: where a
    // rider is drawn over its horse in a colour near the horse's).
    std::size_t differing = 0, outside = 0, covered = 0, coveredDiffering = 0;
    for (std::size_t i = 0; i < riderPixels.size(); ++i) {
        const bool differs = channelDifference(riders.image, horses.image, i) > 2;
        differing += differs;
        outside += differs && riderPixels[i] == 0;
        covered += riderPixels[i] == 2;
        coveredDiffering += riderPixels[i] == 2 && differs;
    }
    EXPECT_GT(differing, 10u * riderCount) << "riders cover pixels";
    EXPECT_EQ(outside, 0u) << "of " << differing << " differing pixels";
    EXPECT_GE(double(coveredDiffering), 0.8 * double(covered)) << coveredDiffering << " of " << covered;
    std::printf("%zu pixels differ, %zu outside the riders; %zu of the riders' %zu pixels differ\n", differing,
                outside, coveredDiffering, covered);
    if (outside != 0 || HasFailure()) {
        app::writePng(test::artifactPath("cavalry-riders.png"), riders.image);
        app::writePng(test::artifactPath("cavalry-horses.png"), horses.image);
    }
}

// The scene's crowd is a column on the march: four times as many ranks deep (z, the way it marches) as
// abreast, riders and foot soldiers 3:1, as the programs build it from the preset.
TEST(CavalryScene, IsAColumnOfRidersAndFootSoldiersOnTheMarch) {
    const app::ScenePreset& preset = app::findScenePreset("cavalry");
    EXPECT_EQ(preset.depthRatio, 4.0f);
    app::SceneOptions scene;
    scene.model = preset.models;
    scene.count = preset.count;
    scene.behaviour = preset.behaviour;
    scene.depthRatio = preset.depthRatio;
    const crowdgpu::Crowd crowd = app::buildCrowd(app::loadModels(scene.model, 1), scene);
    ASSERT_EQ(crowd.size(), 1024u);
    std::set<float> xs, zs;
    std::uint32_t riders = 0;
    for (std::uint32_t c = 0; c < crowd.size(); ++c) {
        const crowdgpu::Character character = crowd.character(c);
        xs.insert(character.position[0]), zs.insert(character.position[2]);
        riders += character.model == 0;
    }
    EXPECT_EQ(xs.size(), 16u) << "abreast";
    EXPECT_EQ(zs.size(), 64u) << "ranks deep";
    EXPECT_NEAR(riders / 1024.0, 0.75, 0.05) << "riders and foot soldiers 3:1";
}

TEST(CavalryScene, AGridsDepthRatioMustBePositive) {
    for (float bad : {0.0f, -1.0f, std::nanf(""), INFINITY}) {
        crowdgpu::GridLayout layout;
        layout.count = 4;
        layout.depthRatio = bad;
        try {
            crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
            ADD_FAILURE() << "depthRatio " << bad << " accepted";
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(e.what()).find("depthRatio"), std::string::npos) << e.what();
        }
    }
}
