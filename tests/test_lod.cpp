// Levels of detail (model::buildLods) and the pose sphere (crowd::computePoseSphere), for the built-in
// characters, the shared glTF assets when present, and hand-built meshes too small to simplify.
#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_test.h"
#include "skin/cpu_skinning.h"
#include "app/crowd_app.h"
#include "crowd/pose_bounds.h"
#include "model/gltf_loader.h"
#include "model/attach_prop.h"
#include "model/lod_builder.h"
#include "model/lod_morph.h"
#include "model/procedural_models.h"
#include "skin/cpu_skinning.h"
#include "support/run_program.h"
#include "support/vertex_matching.h"

namespace {

using model::SkinnedModel;

// ---- The models: as built or read from the file, and as app::loadModel gives them ---------------

struct Character {
    std::string name;
    std::string file;  // under ../shared/assets; empty for a built-in model
};

void PrintTo(const Character& c, std::ostream* out) { *out << c.name; }

std::filesystem::path assetPath(const Character& c) { return std::filesystem::path(CROWD_SHARED_ASSETS_DIR) / c.file; }

std::string loadName(const Character& c) { return c.file.empty() ? c.name : assetPath(c).string(); }

SkinnedModel original(const Character& c) {
    if (c.name == "soldier") return model::makeSoldier(1);
    if (c.name == "horse") return model::makeHorse(1);
    return model::loadGltf(assetPath(c));
}

// app::loadModel builds levels and sphere for each load; the tests share one load per character.
const SkinnedModel& loaded(const Character& c) {
    static std::map<std::string, SkinnedModel> cache;
    auto it = cache.find(c.name);
    if (it == cache.end()) it = cache.emplace(c.name, test::loadModel(loadName(c), 1)).first;
    return it->second;
}

class LodOf : public testing::TestWithParam<Character> {
protected:
    void SetUp() override {
        if (!GetParam().file.empty() && !std::filesystem::exists(assetPath(GetParam())))
            GTEST_SKIP() << "shared asset " << assetPath(GetParam()) << " not present (see ../shared/assets/INVENTORY.md)";
    }
    const SkinnedModel& m() const { return loaded(GetParam()); }
};

std::set<std::uint32_t> usedVertices(const std::vector<std::uint32_t>& indices) {
    return {indices.begin(), indices.end()};
}

glm::dvec3 position(const std::vector<skin::CpuSkinnedVertex>& pose, std::uint32_t v) { return pose[v].position; }

// Every pose the tests look at: the rest pose, and each clip at a few times.
std::vector<std::pair<std::uint32_t, float>> somePoses(const SkinnedModel& m) {
    std::vector<std::pair<std::uint32_t, float>> poses = {{static_cast<std::uint32_t>(m.clips.size()), 0.0f}};
    for (std::uint32_t c = 0; c < m.clips.size(); ++c)
        for (const float fraction : {0.0f, 0.3f, 0.55f, 0.8f}) poses.push_back({c, fraction * m.clips[c].duration});
    return poses;
}

struct Box {
    glm::dvec3 lo{1e30}, hi{-1e30};
    void add(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    double diagonal() const { return glm::length(hi - lo); }
};

}  // namespace

// ---- Budgets and structure --------------------------------------------------------------------

TEST(LodTargets, AreThePapersRatiosOfTheFullMesh) {
    // The paper's soldier: 1,084, 544 and 312 polygons.
    EXPECT_EQ(model::lodTriangleTarget(1084, 0), 1084u);
    EXPECT_EQ(model::lodTriangleTarget(1084, 1), 544u);
    EXPECT_EQ(model::lodTriangleTarget(1084, 2), 312u);
    // Ours: 1,080 and 1,268 triangles.
    EXPECT_EQ(model::lodTriangleTarget(1080, 1), 542u);
    EXPECT_EQ(model::lodTriangleTarget(1080, 2), 311u);
    EXPECT_EQ(model::lodTriangleTarget(1268, 1), 636u);
    EXPECT_EQ(model::lodTriangleTarget(1268, 2), 365u);
    // Never below one triangle.
    EXPECT_EQ(model::lodTriangleTarget(1, 2), 1u);
}

TEST_P(LodOf, HasThreeLevelsTheFirstBeingTheFullMesh) {
    ASSERT_EQ(m().lods.size(), model::kLodLevels);
    EXPECT_EQ(m().lods[0].indices, m().indices);
    EXPECT_EQ(m().lods[0].vertexCount, m().vertices.size());
}

TEST_P(LodOf, LevelsMeetThePapersTriangleBudgetsWithinTenPercent) {
    ASSERT_EQ(m().lods.size(), model::kLodLevels);
    for (std::size_t l = 1; l < model::kLodLevels; ++l) {
        const double target = static_cast<double>(model::lodTriangleTarget(m().triangleCount(), l));
        EXPECT_NEAR(static_cast<double>(m().lods[l].indices.size() / 3), target, 0.1 * target) << "level " << l;
    }
}

TEST_P(LodOf, CoarserLevelsDrawExactlyAPrefixOfTheFinerLevelsVertices) {
    ASSERT_EQ(m().lods.size(), model::kLodLevels);
    for (std::size_t l = 0; l < model::kLodLevels; ++l) {
        const model::SkinnedModel::Lod& level = m().lods[l];
        ASSERT_EQ(level.indices.size() % 3, 0u);
        for (std::uint32_t index : level.indices) ASSERT_LT(index, level.vertexCount) << "level " << l;
        if (l == 0) continue;
        EXPECT_LE(level.vertexCount, m().lods[l - 1].vertexCount) << "level " << l;
        // Exactly the prefix: skinning the first vertexCount vertices skins nothing the level leaves unused.
        EXPECT_EQ(usedVertices(level.indices).size(), level.vertexCount) << "level " << l;
    }
}

TEST_P(LodOf, NoLevelHasADegenerateTriangle) {
    for (std::size_t l = 0; l < m().lods.size(); ++l) {
        const std::vector<std::uint32_t>& indices = m().lods[l].indices;
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
            ASSERT_TRUE(a != b && b != c && a != c) << "level " << l << " triangle " << t / 3;
            const glm::dvec3 pa(m().vertices[a].position), pb(m().vertices[b].position), pc(m().vertices[c].position);
            EXPECT_GT(glm::length(glm::cross(pb - pa, pc - pa)), 0.0) << "level " << l << " triangle " << t / 3;
        }
    }
}

TEST_P(LodOf, EveryTriangleShowsOneMaterial) {
    // Colour edges are seams the simplifier keeps: no triangle blends two materials.
    for (std::size_t l = 0; l < m().lods.size(); ++l) {
        const std::vector<std::uint32_t>& indices = m().lods[l].indices;
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
            const float material = m().vertices[indices[t]].normal.w;
            EXPECT_EQ(m().vertices[indices[t + 1]].normal.w, material) << "level " << l << " triangle " << t / 3;
            EXPECT_EQ(m().vertices[indices[t + 2]].normal.w, material) << "level " << l << " triangle " << t / 3;
        }
    }
}

TEST_P(LodOf, EveryVertexKeepsNormalizedWeightsOverValidJoints) {
    for (const gpu::SkinVertex& v : m().vertices) {
        EXPECT_NEAR(v.weights.x + v.weights.y + v.weights.z + v.weights.w, 1.0f, 1e-5f);
        for (int k = 0; k < MAX_INFLUENCES; ++k) {
            EXPECT_GE(v.weights[k], 0.0f);
            if (v.weights[k] > 0.0f) {
                EXPECT_LT(v.joints[k], m().skeleton.jointCount());
            }
        }
    }
}

TEST_P(LodOf, ReorderedVerticesAreTheOriginalOnesAndLevelZeroDrawsTheSameSurface) {
    const SkinnedModel before = original(GetParam());
    ASSERT_EQ(m().vertices.size(), before.vertices.size());
    ASSERT_EQ(m().uvs.size(), before.uvs.size());
    // A permutation: every vertex is one of the original ones, joints, weights, normal and uv alike.
    const std::vector<std::uint32_t> from = test::originalVertexOf(before, m());
    EXPECT_EQ(std::set<std::uint32_t>(from.begin(), from.end()).size(), before.vertices.size());
    // Level 0 keeps the authored triangle order, so its k-th corner is the original k-th corner and
    // skins to exactly the same place in every pose.
    ASSERT_EQ(m().indices.size(), before.indices.size());
    for (const auto& [clip, time] : somePoses(before)) {
        const std::vector<skin::CpuSkinnedVertex> posed = skin::poseOnCpu(m(), clip, time);
        const std::vector<skin::CpuSkinnedVertex> expected = skin::poseOnCpu(before, clip, time);
        for (std::size_t k = 0; k < before.indices.size(); ++k)
            ASSERT_EQ(position(posed, m().indices[k]), position(expected, before.indices[k]))
                << "corner " << k << ", clip " << clip << " at " << time << " s";
    }
}

TEST_P(LodOf, SimplifiedLevelsSpanTheModelsBoxInEveryPose) {
    // A lost hand, rifle or ear, or a limb folded flat at its joint, would shrink the box: each corner
    // of a level's box stays within 3 % of the full mesh's diagonal.
    for (const auto& [clip, time] : somePoses(m())) {
        const std::vector<skin::CpuSkinnedVertex> posed = skin::poseOnCpu(m(), clip, time);
        std::vector<Box> boxes(m().lods.size());
        for (std::size_t l = 0; l < m().lods.size(); ++l)
            for (std::uint32_t index : m().lods[l].indices) boxes[l].add(position(posed, index));
        const double allowed = 0.03 * boxes[0].diagonal();
        for (std::size_t l = 1; l < m().lods.size(); ++l) {
            EXPECT_LE(glm::length(boxes[l].lo - boxes[0].lo), allowed) << "level " << l << ", clip " << clip << " at " << time;
            EXPECT_LE(glm::length(boxes[l].hi - boxes[0].hi), allowed) << "level " << l << ", clip " << clip << " at " << time;
        }
    }
}

TEST_P(LodOf, BuildingTwiceGivesTheSameLevels) {
    SkinnedModel first = original(GetParam()), second = original(GetParam());
    model::buildLods(first);
    model::buildLods(second);
    ASSERT_EQ(first.lods.size(), second.lods.size());
    for (std::size_t l = 0; l < first.lods.size(); ++l) {
        EXPECT_EQ(first.lods[l].indices, second.lods[l].indices);
        EXPECT_EQ(first.lods[l].vertexCount, second.lods[l].vertexCount);
    }
    std::vector<std::uint32_t> sameOrder(first.vertices.size());
    std::iota(sameOrder.begin(), sameOrder.end(), 0u);
    EXPECT_EQ(test::originalVertexOf(first, second), sameOrder);
}

// ---- The pose sphere --------------------------------------------------------------------------

// Geomorphs (model/lod_morph.h): every vertex a coarser level drops targets a point of one of that
// level's triangles, on its own part (body or prop), near it in the bind pose; every other vertex
// targets itself. The distance is the simplifier's error at that vertex, a small share of the model.
TEST_P(LodOf, EveryVertexACoarserLevelDropsMorphsOntoThatLevelNearby) {
    ASSERT_EQ(m().lods.size(), model::kLodLevels);
    const std::vector<model::LodMorphTarget> targets = model::lodMorphTargets(m(), m().lods);
    ASSERT_EQ(targets.size(), m().vertices.size());
    auto part = [&](std::uint32_t v) {
        const std::uint32_t joint = m().vertices[v].joints.x;
        return joint < m().skeleton.propOfJoint.size() ? m().skeleton.propOfJoint[joint] : 0u;
    };
    Box box;
    for (const gpu::SkinVertex& v : m().vertices) box.add(glm::dvec3(v.position));
    double farthest = 0.0, sum = 0.0;
    std::size_t moving = 0;
    for (std::size_t l = 0; l + 1 < model::kLodLevels; ++l) {
        const std::vector<std::uint32_t>& coarse = m().lods[l + 1].indices;
        std::set<std::array<std::uint32_t, 3>> coarseTriangles;
        for (std::size_t t = 0; t + 2 < coarse.size(); t += 3) coarseTriangles.insert({coarse[t], coarse[t + 1], coarse[t + 2]});
        const std::set<std::uint32_t> used = usedVertices(m().lods[l].indices);
        for (std::uint32_t v = m().lods[l + 1].vertexCount; v < m().lods[l].vertexCount; ++v) {
            if (!used.count(v)) continue;
            const model::LodMorphTarget& t = targets[v];
            ASSERT_TRUE(coarseTriangles.count(t.corners)) << "vertex " << v << " of level " << l;
            EXPECT_GE(t.weights.x, 0.0f);
            EXPECT_GE(t.weights.y, 0.0f);
            EXPECT_LE(t.weights.x + t.weights.y, 1.0f + 1e-6f);
            EXPECT_EQ(part(t.corners[0]), part(v)) << "vertex " << v << " morphs onto another part";
            const glm::dvec3 target = (1.0 - t.weights.x - t.weights.y) * glm::dvec3(m().vertices[t.corners[0]].position) +
                                      double(t.weights.x) * glm::dvec3(m().vertices[t.corners[1]].position) +
                                      double(t.weights.y) * glm::dvec3(m().vertices[t.corners[2]].position);
            const double distance = glm::length(target - glm::dvec3(m().vertices[v].position));
            farthest = std::max(farthest, distance), sum += distance, ++moving;
        }
    }
    for (std::uint32_t v = 0; v < m().lods.back().vertexCount; ++v) {
        EXPECT_EQ(targets[v].corners, (std::array<std::uint32_t, 3>{v, v, v}));
        EXPECT_EQ(targets[v].weights, glm::vec2(0.0f));
    }
    std::printf("%s: %zu vertices morph, %.4f of the box's diagonal on average, %.4f at most\n", GetParam().name.c_str(),
                moving, sum / double(std::max<std::size_t>(moving, 1)) / box.diagonal(), farthest / box.diagonal());
    EXPECT_GT(moving, 0u);
    EXPECT_LT(farthest, 0.1 * box.diagonal());
}

TEST_P(LodOf, PoseSphereHoldsEveryVertexAtRandomTimesOfEveryClipButIsNotLoose) {
    const glm::dvec3 center(m().poseSphere);
    const double radius = m().poseSphere.w;
    ASSERT_GT(radius, 0.0);
    // Times drawn at random are (almost surely) none of the sphere's samples.
    std::mt19937 random(20240611);
    double farthest = 0.0;
    for (std::uint32_t clip = 0; clip <= m().clips.size(); ++clip) {  // clips.size(): the rest pose
        const float duration = clip < m().clips.size() ? m().clips[clip].duration : 0.0f;
        std::uniform_real_distribution<float> times(0.0f, duration);
        for (int sample = 0; sample < 40; ++sample) {
            const float time = times(random);
            const std::vector<skin::CpuSkinnedVertex> posed = skin::poseOnCpu(m(), clip, time);
            for (std::size_t i = 0; i < posed.size(); ++i) {
                // The sphere holds the props most of a crowd carries, not the rare ones (the soldier's
                // flag; docs/props.md): those are left out here as there.
                if (model::onPropLeftOut(m(), m().vertices[i], model::propsMostCarry(m()))) continue;
                const skin::CpuSkinnedVertex& v = posed[i];
                const double distance = glm::length(v.position - center);
                ASSERT_LE(distance, radius) << "clip " << clip << " at " << time << " s";
                farthest = std::max(farthest, distance);
            }
        }
    }
    EXPECT_LT(radius, 1.5 * farthest);
}

INSTANTIATE_TEST_SUITE_P(Characters, LodOf,
                         testing::Values(Character{"soldier", ""}, Character{"horse", ""},
                                         Character{"Fox", "fox/Fox.glb"},
                                         Character{"CesiumMan", "cesium-man/CesiumMan.glb"},
                                         Character{"RiggedSimple", "rigged-simple/RiggedSimple.glb"}),
                         [](const testing::TestParamInfo<Character>& info) { return info.param.name; });

// ---- Meshes too small to simplify ---------------------------------------------------------------

namespace {

// A rigid mesh on one joint (the pose sphere needs a skeleton; LODs do not).
SkinnedModel handBuilt(const std::vector<glm::vec3>& positions, std::vector<std::uint32_t> indices) {
    SkinnedModel m;
    m.skeleton.parents = {-1};
    m.skeleton.restPose = {anim::Transform{}};
    m.skeleton.inverseBind = {glm::mat4(1.0f)};
    for (const glm::vec3& p : positions)
        m.vertices.push_back({glm::vec4(p, 1.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), glm::uvec4(0), glm::vec4(1, 0, 0, 0)});
    m.indices = std::move(indices);
    return m;
}

// A triangle list's faces, each rotated to start at its lowest index (which keeps its winding).
std::set<std::array<std::uint32_t, 3>> faces(const std::vector<std::uint32_t>& indices) {
    std::set<std::array<std::uint32_t, 3>> result;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::array<std::uint32_t, 3> face = {indices[t], indices[t + 1], indices[t + 2]};
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        result.insert(face);
    }
    return result;
}

}  // namespace

TEST(LodOfATinyMesh, ASingleTriangleIsEveryLevel) {
    SkinnedModel m = handBuilt({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2});
    model::buildLods(m);
    ASSERT_EQ(m.lods.size(), 3u);
    for (const model::SkinnedModel::Lod& level : m.lods) {
        EXPECT_EQ(level.indices, (std::vector<std::uint32_t>{0, 1, 2}));
        EXPECT_EQ(level.vertexCount, 3u);
    }
}

TEST(LodOfATinyMesh, ATetrahedronKeepsItsFourTrianglesRatherThanFlattenIntoASheet) {
    // Budgets 2 and 1 triangles: the simplifier could only fold it into one triangle both ways round,
    // a part with no inside, so every level keeps the tetrahedron.
    SkinnedModel m = handBuilt({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
    model::buildLods(m);
    ASSERT_EQ(m.lods.size(), 3u);
    for (const model::SkinnedModel::Lod& level : m.lods) {
        EXPECT_EQ(level.indices.size(), 12u);
        EXPECT_EQ(level.vertexCount, 4u);
        // The same four faces, wound the same way (a level may order them for the vertex cache).
        EXPECT_EQ(faces(level.indices), faces(m.indices));
    }
}

TEST(LodOfATinyMesh, AMeshWithoutTrianglesHasThreeEmptyLevels) {
    SkinnedModel m = handBuilt({{0, 0, 0}}, {});
    model::buildLods(m);
    ASSERT_EQ(m.lods.size(), 3u);
    EXPECT_EQ(m.lods[0].vertexCount, 1u);
    for (std::size_t l = 1; l < 3; ++l) EXPECT_EQ(m.lods[l].vertexCount, 0u);
    for (const model::SkinnedModel::Lod& level : m.lods) EXPECT_TRUE(level.indices.empty());
}

// A square of four corners and a raised centre (a flat pyramid, four triangles) over the square as two
// triangles: the centre, the one vertex the coarser level drops, morphs straight down onto the
// diagonal the two share, half way along it, in the first of them (ties go to the first triangle).
// The coarsest level drops nothing, and the corners stay where they are.
TEST(LodMorphOfAHandBuiltMesh, TheCentreOfAPyramidMorphsOntoTheSquareBelowIt) {
    SkinnedModel m = handBuilt({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 0.2f}},
                               {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
    const std::vector<SkinnedModel::Lod> lods = {{m.indices, 5}, {{0, 1, 2, 0, 2, 3}, 4}, {{0, 1, 2, 0, 2, 3}, 4}};
    const std::vector<model::LodMorphTarget> targets = model::lodMorphTargets(m, lods);
    ASSERT_EQ(targets.size(), 5u);
    EXPECT_EQ(targets[4].corners, (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_NEAR(targets[4].weights.x, 0.0f, 1e-6f);
    EXPECT_NEAR(targets[4].weights.y, 0.5f, 1e-6f);
    for (std::uint32_t v = 0; v < 4; ++v) EXPECT_EQ(targets[v].corners, (std::array<std::uint32_t, 3>{v, v, v}));
    // Packed as the GPU reads it: the second corner's weight in the low half, as unorm16.
    EXPECT_EQ(model::packLodMorphTarget(targets[4]), glm::uvec4(0, 1, 2, 0u | (32768u << 16)));
}

TEST(PoseSphere, OfAStillMeshIsItsBoxsCircumsphereWithTheMargin) {
    // No clips: only the rest pose, a unit square in the xy plane centred on (0.5, 0.5, 0).
    const SkinnedModel m = handBuilt({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3});
    const glm::vec4 sphere = crowd::computePoseSphere(m);
    EXPECT_FLOAT_EQ(sphere.x, 0.5f);
    EXPECT_FLOAT_EQ(sphere.y, 0.5f);
    EXPECT_FLOAT_EQ(sphere.z, 0.0f);
    EXPECT_FLOAT_EQ(sphere.w, 1.01f * std::sqrt(0.5f));
}

TEST(PoseSphere, OfAModelWithoutVerticesIsZero) {
    EXPECT_EQ(crowd::computePoseSphere(SkinnedModel{}), glm::vec4(0.0f));
}

// ---- crowd-render --list-clips ---------------------------------------------------------------------

TEST(LodListing, ListClipsPrintsEveryLevelAndThePoseSphere) {
    const test::ProgramResult r = test::runProgram(CROWD_RENDER_BINARY, "--model soldier --list-clips");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const SkinnedModel& soldier = loaded({"soldier", ""});
    for (std::size_t l = 0; l < soldier.lods.size(); ++l) {
        const std::string line = "LOD " + std::to_string(l) + ": " + std::to_string(soldier.lods[l].indices.size() / 3) +
                                 " triangles, " + std::to_string(soldier.lods[l].vertexCount) + " vertices";
        EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
    }
    // The body's 1,020 triangles and its props (a rifle, 60, and a flag, 36: docs/props.md).
    EXPECT_NE(r.out.find("LOD 0: 1116 triangles, 882 vertices"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pose sphere: centre ("), std::string::npos) << r.out;
}
