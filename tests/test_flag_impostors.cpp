// Props in the impostor atlas: a model has a set of cells for each props mask its characters carry
// (render/impostor_prop_sets.h), chosen per character on the GPU from its mask. The choice by hand, the
// sets a crowd gets, a flag carrier's impostor against a non-carrier's (the pixels that differ lie where
// the CPU puts the flag's triangles on the impostor's quad), and a carrier whose set the budget dropped
// showing the nearest set. The switch-size agreement for flag carriers is in test_impostors.cpp.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "app/png_writer.h"
#include "model/attach_prop.h"
#include "model/prop_mesh.h"
#include "render/impostor_atlas.h"
#include "render/impostor_cell.h"
#include "render/impostor_prop_sets.h"
#include "skin/cpu_skinning.h"
#include "support/gpu_test.h"

namespace {

constexpr std::uint32_t kRifle = 0x1u, kRifleAndFlag = 0x3u;

}  // namespace

// Set s at distance d (props differing): the fewest differing wins, the more carried (lower) set on a tie.
TEST(ImpostorPropSets, ACharacterShowsTheNearestSetTheMoreCarriedOnATie) {
    gpu::ImpostorModel m{};
    m.cells.w = 3;
    m.propSets = glm::uvec4(0b01u, 0b11u, 0b00u, 0u);
    EXPECT_EQ(render::impostorPropSet(m, 0b01u), 0u);
    EXPECT_EQ(render::impostorPropSet(m, 0b11u), 1u);
    EXPECT_EQ(render::impostorPropSet(m, 0b00u), 2u);
    // 0b10 differs from 0b01 in two props, from 0b11 and from 0b00 in one: set 1, the more carried.
    EXPECT_EQ(render::impostorPropSet(m, 0b10u), 1u);
    // A third prop no set has: one from 0b11.
    EXPECT_EQ(render::impostorPropSet(m, 0b111u), 1u);
    // One set: everyone shows it (the 4th entry, unused, is never looked at).
    m.cells.w = 1;
    m.propSets.w = 0b11u;
    EXPECT_EQ(render::impostorPropSet(m, 0b11u), 0u);
}

// A crowd's sets: per model its characters' masks, most carried first, ties to the smaller mask, at most
// IMPOSTOR_SETS; a model nobody plays gets the props most carry by default.
TEST(ImpostorPropSets, AModelsMasksMostCarriedFirstAtMostFour) {
    model::SkinnedModel soldier = test::loadModel("soldier", 1);
    model::attachProp(soldier, model::makeFlag(), "head", glm::mat4(1.0f), 0.0f);  // prop 2: 8 masks possible
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    std::vector<crowd::Character> characters;
    const std::pair<std::uint32_t, int> carried[] = {{0b001, 5}, {0b111, 1}, {0b011, 3}, {0b000, 3}, {0b101, 2}};
    for (const auto& [mask, count] : carried)
        for (int i = 0; i < count; ++i) {
            crowd::Character c;
            c.props = mask;
            c.position = glm::vec3(3.0f * static_cast<float>(characters.size()), 0.0f, 0.0f);
            characters.push_back(c);
        }
    crowd::Crowd crowd({&soldier, &horse}, characters);
    const std::vector<std::vector<std::uint32_t>> sets = render::impostorPropSets(crowd);
    ASSERT_EQ(sets.size(), 2u);
    EXPECT_EQ(sets[0], (std::vector<std::uint32_t>{0b001, 0b000, 0b011, 0b101}));  // 0b111 (one carrier) left out
    EXPECT_EQ(sets[1], (std::vector<std::uint32_t>{model::propsMostCarry(horse)}));
}

namespace {

using test::GpuTest;

constexpr float kDegree = 3.14159265f / 180.0f;
constexpr std::uint32_t kSide = 96;

struct ImpostorShot {
    app::Rgba8Image image;
    glm::mat4 viewProjection;
    std::shared_ptr<const render::ImpostorAtlas> atlas;
};

// The camera at the atlas's own view of cell (azimuth step 4, band 0): from +x (the soldier's left, the
// flag's side: the cloth faces it) at the band's middle elevation (11.25 degrees) above the pose sphere's
// centre, so a soldier facing +z shows one cell unblended (its azimuth is the step's, and at phase 0 its
// frame too), its pose sphere 40 px across.
constexpr std::uint32_t kAzimuthStep = 4;  // of 16: 90 degrees from +z towards +x
render::Camera atlasViewCamera(const model::SkinnedModel& soldier) {
    render::Camera camera;
    const float focal = static_cast<float>(kSide) / (2.0f * std::tan(0.5f * camera.verticalFov));
    const float distance = 2.0f * soldier.poseSphere.w * focal / 40.0f;
    camera.target = glm::vec3(soldier.poseSphere);
    camera.eye = camera.target + distance * glm::vec3(std::cos(11.25f * kDegree), std::sin(11.25f * kDegree), 0.0f);
    camera.eye.z = camera.target.z;  // exactly: the direction's azimuth is 90 degrees
    camera.nearPlane = 0.5f;
    camera.farPlane = 4.0f * distance;
    return camera;
}

// Two soldiers standing (idle at phase 0, the atlas's frame 0): the first at the origin facing +z carrying
// `shown`, the second behind the camera carrying `other`, so a crowd of either order has both masks and
// the same cell sets. The first is an impostor (under the 49 px threshold). No shadows: the flag's would
// fall outside its own projection.
ImpostorShot renderImpostor(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, std::uint32_t shown,
                            std::uint32_t other, std::shared_ptr<const render::ImpostorAtlas> atlas,
                            std::uint64_t budget = render::ImpostorSettings{}.budgetPerModel) {
    std::vector<crowd::Character> characters(2);
    for (crowd::Character& c : characters) c.clip = static_cast<std::uint32_t>(soldier.findClip("idle"));
    characters[0].props = shown;
    characters[1].props = other;
    characters[1].position = glm::vec3(0.0f, 0.0f, 200.0f);
    crowd::Crowd crowd(soldier, characters);
    test::RendererOptions options;
    options.size = {kSide, kSide};
    options.method = skin::Method::Compute;
    options.shadows = false;
    options.cull.impostors = true;
    options.cull.impostorThreshold = 49.0f;
    options.cull.hysteresis = 0.0f;
    options.impostorSettings.budgetPerModel = budget;
    options.atlas = atlas;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera = test::appCamera(atlasViewCamera(soldier));
    renderer.renderFrame(0.0f);
    renderer.finish();
    EXPECT_EQ(renderer.takeStats().back().lods.impostors, 1u);
    return {renderer.readback(), test::internalCamera(renderer.camera).viewProjection(1.0f), renderer.impostorAtlas()};
}

// Where the impostor shows the flag: the flag's triangles at frame 0 (the crowd's CPU bones, skinned by the
// CPU reference), projected orthographically onto the quad's plane (through the pose sphere's centre,
// facing the capture direction: what the cell holds), then by the camera; pixels whose centre a triangle
// covers, grown by one pixel (the atlas is filtered). `flag` false: the rest (body and rifle), not grown.
std::vector<bool> onTheQuad(const model::SkinnedModel& soldier, const render::ImpostorAtlas& atlas,
                            const glm::mat4& viewProjection, bool flag) {
    crowd::Character c;
    c.clip = static_cast<std::uint32_t>(soldier.findClip("idle"));
    c.props = kRifleAndFlag;
    crowd::Crowd reference(soldier, {c});
    std::vector<gpu::BoneRows> bones(soldier.skeleton.jointCount());
    reference.animateCharacter(0, 0.0, bones);
    const std::vector<skin::CpuSkinnedVertex> posed = skin::skinOnCpu(soldier, bones);
    const gpu::ImpostorModel& cells = atlas.plan().set(0, 0);
    const glm::vec3 towards = render::impostorViewDirection(cells, kAzimuthStep, 0);
    glm::vec3 right, up;
    render::impostorBasis(towards, right, up);
    const glm::vec3 centre(cells.square);
    auto pixel = [&](const glm::dvec3& p) {
        const glm::vec3 d = glm::vec3(p) - centre;
        const glm::vec3 onQuad = centre + glm::dot(d, right) * right + glm::dot(d, up) * up;
        const glm::vec4 clip = viewProjection * glm::vec4(onQuad, 1.0f);
        return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * kSide, (clip.y / clip.w * 0.5f + 0.5f) * kSide);
    };
    const std::uint32_t flagJoint = soldier.props[1].joint;
    std::vector<bool> cover(std::size_t{kSide} * kSide, false);
    for (std::size_t t = 0; t + 2 < soldier.indices.size(); t += 3) {
        const std::uint32_t a = soldier.indices[t], b = soldier.indices[t + 1], v = soldier.indices[t + 2];
        const bool onFlag = soldier.vertices[a].joints.x == flagJoint && soldier.vertices[b].joints.x == flagJoint &&
                            soldier.vertices[v].joints.x == flagJoint;
        if (onFlag != flag) continue;
        const glm::vec2 p0 = pixel(posed[a].position), p1 = pixel(posed[b].position), p2 = pixel(posed[v].position);
        auto edge = [](glm::vec2 u, glm::vec2 w, glm::vec2 q) { return (w.x - u.x) * (q.y - u.y) - (w.y - u.y) * (q.x - u.x); };
        const float area = edge(p0, p1, p2);
        if (area == 0.0f) continue;
        for (std::uint32_t y = 0; y < kSide; ++y)
            for (std::uint32_t x = 0; x < kSide; ++x) {
                const glm::vec2 q(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                if (edge(p1, p2, q) / area >= 0 && edge(p2, p0, q) / area >= 0 && edge(p0, p1, q) / area >= 0)
                    cover[std::size_t{y} * kSide + x] = true;
            }
    }
    if (!flag) return cover;
    std::vector<bool> grown = cover;
    for (int y = 0; y < static_cast<int>(kSide); ++y)
        for (int x = 0; x < static_cast<int>(kSide); ++x)
            if (cover[static_cast<std::size_t>(y) * kSide + x])
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u >= 0 && v >= 0 && u < static_cast<int>(kSide) && v < static_cast<int>(kSide))
                            grown[static_cast<std::size_t>(v) * kSide + u] = true;
                    }
    return grown;
}

// Pixels within one pixel of the edge of `cover` (covered and uncovered pixels among the 3x3 around them).
std::vector<bool> edgeBand(const std::vector<bool>& cover) {
    std::vector<bool> band(cover.size(), false);
    for (int y = 0; y < static_cast<int>(kSide); ++y)
        for (int x = 0; x < static_cast<int>(kSide); ++x) {
            bool in = false, out = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    const bool covered = u >= 0 && v >= 0 && u < static_cast<int>(kSide) && v < static_cast<int>(kSide) &&
                                         cover[static_cast<std::size_t>(v) * kSide + u];
                    (covered ? in : out) = true;
                }
            band[static_cast<std::size_t>(y) * kSide + x] = in && out;
        }
    return band;
}

bool differsBy(const app::Rgba8Image& a, const app::Rgba8Image& b, std::size_t i, int levels) {
    for (int ch = 0; ch < 3; ++ch)
        if (std::abs(int(a.pixels[4 * i + ch]) - int(b.pixels[4 * i + ch])) > levels) return true;
    return false;
}

}  // namespace

// A flag carrier's impostor against a non-carrier's (rifle alone), the same soldier, pose and view (its
// left, where the cloth shows): the pixels that differ lie where the flag's triangles fall on the
// impostor's quad, and cover much of it. Before, both showed the atlas's one picture (the rifle): no pixel
// differed. The carrier's cells are framed wider (the flag reaches beyond the pose sphere), so its body is
// resampled from another scale and its silhouette may move by a pixel: differences within a pixel of the
// body's projected edge are not counted as the flag's, nor against it.
TEST_F(GpuTest, AFlagCarriersImpostorShowsTheFlagWhereItsTrianglesFallOnTheQuad) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const ImpostorShot carrier = renderImpostor(*context, soldier, kRifleAndFlag, kRifle, nullptr);
    const ImpostorShot without = renderImpostor(*context, soldier, kRifle, kRifleAndFlag, carrier.atlas);
    const render::ImpostorPlan& plan = carrier.atlas->plan();
    ASSERT_EQ(plan.setCount(0), 2u);
    std::printf("cell squares: rifle %.3f m, rifle and flag %.3f m (half sides)\n", plan.set(0, 0).square.w,
                plan.set(0, 1).square.w);
    const std::vector<bool> flag = onTheQuad(soldier, *carrier.atlas, carrier.viewProjection, true);
    const std::vector<bool> bodyEdge = edgeBand(onTheQuad(soldier, *carrier.atlas, carrier.viewProjection, false));
    std::size_t differing = 0, inside = 0, flagPixels = 0;
    for (std::size_t i = 0; i < flag.size(); ++i) {
        if (bodyEdge[i]) continue;
        const bool differs = differsBy(carrier.image, without.image, i, 8);
        differing += differs;
        inside += differs && flag[i];
        flagPixels += flag[i];
    }
    std::printf("off the body's edge: %zu pixels differ by over 8 levels, %zu inside the flag's projection (%zu pixels)\n",
                differing, inside, flagPixels);
    EXPECT_GT(differing, 60u);
    EXPECT_GE(static_cast<double>(inside), 0.98 * static_cast<double>(differing));
    EXPECT_GE(static_cast<double>(differing), 0.4 * static_cast<double>(flagPixels));
    if (std::getenv("CROWD_KEEP_IMAGES")) {
        app::writePng(test::artifactPath("flag-impostor-carrier.png"), carrier.image);
        app::writePng(test::artifactPath("flag-impostor-without.png"), without.image);
    }
}

// With a budget for one cell set the rarer mask's set is dropped: the flag carrier shows the nearest set
// kept (the rifle's), the very picture of the non-carrier.
TEST_F(GpuTest, AFlagCarrierWhoseSetTheBudgetDroppedShowsTheNearestSet) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const ImpostorShot without = renderImpostor(*context, soldier, kRifle, kRifleAndFlag, nullptr);
    const std::uint64_t oneSet = without.atlas->plan().bytesOf(0) / 2;
    const ImpostorShot carrier = renderImpostor(*context, soldier, kRifleAndFlag, kRifle, nullptr, oneSet);
    ASSERT_EQ(carrier.atlas->plan().setCount(0), 1u);
    std::printf("atlas bytes: two sets %.1f MiB, one set %.1f MiB\n", static_cast<double>(without.atlas->bytes()) / 1048576.0,
                static_cast<double>(carrier.atlas->bytes()) / 1048576.0);
    EXPECT_EQ(carrier.atlas->plan().bytes() * 2, without.atlas->plan().bytes());
    EXPECT_EQ(carrier.atlas->plan().set(0, 0).propSets.x, kRifle);
    EXPECT_EQ(carrier.atlas->plan().set(0, 0).cells.z, without.atlas->plan().set(0, 0).cells.z);  // frames kept
    EXPECT_EQ(test::fractionOfMatchingPixels(carrier.image, without.image, 0), 1.0);
}
