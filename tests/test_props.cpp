// Props on joints (docs/props.md): a prop's skinned vertices are its joint's world transform times its
// offset times its own vertices, by every skinning method; its pixels appear where the CPU projection of
// those vertices puts them and vanish when a character does not carry it; a missing joint is one error.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "app/crowd_app.h"
#include "app/crowd_renderer.h"
#include "crowd/pose_bounds.h"
#include "crowdgpu/crowdgpu.h"
#include "crowdgpu/model.hpp"
#include "gpu/error.h"
#include "model/attach_prop.h"
#include "model/lod_builder.h"
#include "model/procedural_models.h"
#include "skin/cpu_skinning.h"
#include "model/gltf_prop.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

// An offset with every part a bug could drop: a rotation about a slanted axis, a uniform scale, a translation.
glm::mat4 testOffset() {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.05f, 0.12f, -0.07f));
    m = glm::rotate(m, glm::radians(35.0f), glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    return glm::scale(m, glm::vec3(1.3f));
}

// The soldier with a third prop, a flag on its head at testOffset(), levels and sphere built again.
struct SoldierWithTestProp {
    model::SkinnedModel model = model::makeSoldier(1);
    std::uint32_t propJoint = 0, head = 0;
    SoldierWithTestProp() {
        model::attachProp(model, model::makeFlag(), "head", testOffset());
        propJoint = model.props.back().joint;
        head = model.props.back().attachedTo;
        model::buildLods(model);
        model.poseSphere = crowd::computePoseSphere(model);
    }
};

glm::dvec3 applyAffine(const anim::Affine& a, const glm::dvec3& p) {
    const glm::dvec4 q(p, 1.0);
    return {glm::dot(glm::dvec4(a.row0), q), glm::dot(glm::dvec4(a.row1), q), glm::dot(glm::dvec4(a.row2), q)};
}

// Culling off, and level-of-detail thresholds that put every character at `level`: none reaches them
// (level 2), every one passes the second but not the first (level 1), or no LOD (level 0).
render::CullSettings atLevel(std::uint32_t level) {
    render::CullSettings cull;
    cull.mode = render::CullMode::Off;
    cull.lod = level > 0;
    cull.lodThresholds[0] = 1e6f;
    cull.lodThresholds[1] = level == 1 ? 1e-3f : 1e5f;
    return cull;
}

// A triangle as its three corners in the prop's own space, rounded to 0.1 mm, rotated to start at its
// smallest corner (so the same triangle compares equal whichever corner a list starts at).
using LocalTriangle = std::array<std::array<long, 3>, 3>;
LocalTriangle localTriangle(std::array<glm::dvec3, 3> corners) {
    LocalTriangle t;
    for (std::size_t k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) t[k][static_cast<std::size_t>(i)] = std::lround(corners[k][i] * 1e4);
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

// The triangles of `m`'s level `level` on joint `propJoint`, in the prop's own space (through the
// joint's inverse bind matrix, which is (jointBind * offset)^-1).
std::multiset<LocalTriangle> propTrianglesAtLevel(const model::SkinnedModel& m, std::uint32_t propJoint, std::size_t level) {
    const glm::dmat4 toLocal(m.skeleton.inverseBind[propJoint]);
    std::multiset<LocalTriangle> out;
    const std::vector<std::uint32_t>& indices = m.lods[level].indices;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        if (m.vertices[indices[t]].joints.x != propJoint) continue;
        std::array<glm::dvec3, 3> corners;
        for (std::size_t k = 0; k < 3; ++k)
            corners[k] = glm::dvec3(toLocal * glm::dvec4(glm::dvec3(glm::vec3(m.vertices[indices[t + k]].position)), 1.0));
        out.insert(localTriangle(corners));
    }
    return out;
}

// The prop mesh's own triangles at `level`, in its space.
std::multiset<LocalTriangle> meshTrianglesAtLevel(const model::PropMesh& prop, std::size_t level) {
    std::multiset<LocalTriangle> out;
    const std::vector<std::uint32_t>& indices = prop.levels[level];
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::array<glm::dvec3, 3> corners;
        for (std::size_t k = 0; k < 3; ++k) corners[k] = glm::dvec3(glm::vec3(prop.vertices[indices[t + k]].position));
        out.insert(localTriangle(corners));
    }
    return out;
}

std::size_t distinctVertices(const std::vector<std::uint32_t>& indices) {
    return std::set<std::uint32_t>(indices.begin(), indices.end()).size();
}

std::vector<crowd::Character> fourCharacters(const model::SkinnedModel& m) {
    std::vector<crowd::Character> characters(4);
    for (std::uint32_t i = 0; i < 4; ++i) {
        characters[i].clip = i % static_cast<std::uint32_t>(m.clips.size());
        characters[i].timeOffset = 0.31f * static_cast<float>(i);
        characters[i].position = glm::vec3(2.5f * static_cast<float>(i), 0.0f, 0.0f);
        characters[i].heading = 0.7f * static_cast<float>(i);
        characters[i].props = 0x7u;  // both of the soldier's props and the test's
    }
    return characters;
}

}  // namespace

namespace {

// Renders four characters of `m` at every level with each method and checks that the GPU's skinned
// vertices of the prop's triangles at that level equal jointWorld(parent) * offset * local, `local`
// recovered from the bind pose through the parent's bind transform and `offset` (not through the prop
// joint the library made). Returns the number of vertices checked.
std::size_t expectPropAtJointTimesOffsetAtEveryLevel(const gpu::VulkanContext& context, const model::SkinnedModel& m,
                                                     std::uint32_t propJoint, std::uint32_t parent, const glm::mat4& offsetMatrix,
                                                     const std::vector<skin::Method>& methods) {
    const glm::dmat4 toLocal = glm::inverse(glm::dmat4(glm::inverse(m.skeleton.inverseBind[parent])) * glm::dmat4(offsetMatrix));
    const glm::dmat4 offset(offsetMatrix);
    std::size_t checked = 0, expectedChecks = 0;
    for (std::uint32_t level = 0; level < model::kLodLevels; ++level) {
        // The vertices the prop's triangles use at this level (its own levels, docs/props.md).
        std::set<std::uint32_t> propVertices;
        for (std::uint32_t index : m.lods[level].indices)
            if (m.vertices[index].joints.x == propJoint) propVertices.insert(index);
        EXPECT_FALSE(propVertices.empty()) << "level " << level;
        for (skin::Method method : methods) {
            if (method == skin::Method::Static && level > 0) continue;  // static skins the full mesh only
            crowd::Crowd crowd(m, fourCharacters(m));
            test::RendererOptions options;
            options.size = {64, 64};
            options.method = method;
            options.cull = atLevel(level);
            test::TestRenderer renderer(context, crowd, options);
            const float time = 0.9f;
            renderer.renderFrame(time);
            renderer.finish();
            double worst = 0.0;
            const std::map<std::uint32_t, test::DrawnCharacter> drawn = test::readDrawList(context, renderer);
            EXPECT_EQ(drawn.size(), crowd.size());
            for (const auto& [c, where] : drawn) {
                EXPECT_EQ(where.lod, level) << "character " << c;
                const test::ReadbackVertices gpu =
                    test::readSkinnedVertices(context, renderer.method().skinnedVertices(), where.firstVertex, where.vertexCount);
                const anim::Affine joint = crowd.jointWorld(c, parent, time);
                for (std::uint32_t v : propVertices) {
                    if (v >= where.vertexCount) {
                        ADD_FAILURE() << "level " << level << " draws vertex " << v << " beyond its " << where.vertexCount;
                        continue;
                    }
                    const glm::dvec3 local(toLocal * glm::dvec4(glm::dvec3(glm::vec3(m.vertices[v].position)), 1.0));
                    const glm::dvec3 expected = applyAffine(joint, glm::dvec3(offset * glm::dvec4(local, 1.0)));
                    worst = std::max(worst, glm::length(glm::dvec3(gpu.positions[v]) - expected));
                    ++checked;
                }
                expectedChecks += propVertices.size();
            }
            // float32 skinning a few metres from the origin: 1e-5 of the height, as the skinning tests allow.
            EXPECT_LE(worst, 1e-5 * m.height()) << skin::methodName(method) << " level " << level;
        }
    }
    EXPECT_EQ(checked, expectedChecks);
    return checked;
}

}  // namespace

TEST_F(GpuTest, PropVerticesAreJointWorldTimesOffsetTimesLocalForEveryMethodThatStoresVertices) {
    const SoldierWithTestProp s;
    const std::size_t checked = expectPropAtJointTimesOffsetAtEveryLevel(
        *context, s.model, s.propJoint, s.head, testOffset(),
        {skin::Method::Compute, skin::Method::TwoPass, skin::Method::TwoPassDirect, skin::Method::Static});
    EXPECT_GE(checked, 4u * 4u * model::makeFlag().vertices.size());  // level 0 alone: every flag vertex
}

TEST(Props, CpuPalettesPlaceThePropAtJointTimesOffsetAndCollapseItWhenNotCarried) {
    const SoldierWithTestProp s;
    const model::SkinnedModel& m = s.model;
    std::vector<crowd::Character> characters = fourCharacters(m);
    characters[1].props = 0x3u;  // not the test's prop
    crowd::Crowd crowd(m, characters);
    const glm::dmat4 toLocal = glm::inverse(glm::dmat4(glm::inverse(m.skeleton.inverseBind[s.head])) * glm::dmat4(testOffset()));
    std::vector<gpu::BoneRows> bones(m.skeleton.jointCount());
    for (double time : {0.0, 0.4, 1.7}) {
        for (std::uint32_t c = 0; c < 2; ++c) {
            crowd.animateCharacter(c, time, bones);
            const std::vector<skin::CpuSkinnedVertex> skinned = skin::skinOnCpu(m, bones);
            const anim::Affine head = crowd.jointWorld(c, s.head, time);
            const glm::dvec3 joint = applyAffine(head, glm::dvec3(glm::dmat4(testOffset())[3]));
            for (std::size_t v = 0; v < m.vertices.size(); ++v) {
                if (m.vertices[v].joints.x != s.propJoint) continue;
                const glm::dvec3 local(toLocal * glm::dvec4(glm::dvec3(glm::vec3(m.vertices[v].position)), 1.0));
                const glm::dvec3 carried = applyAffine(head, glm::dvec3(glm::dmat4(testOffset()) * glm::dvec4(local, 1.0)));
                // Carried: where the joint and offset put it; not carried: on the prop's joint, a point.
                const glm::dvec3 expected = c == 0 ? carried : joint;
                EXPECT_LE(glm::length(skinned[v].position - expected), 1e-5 * m.height()) << "character " << c << " t " << time;
            }
        }
    }
}

TEST(Props, EachLevelDrawsTheBodysOwnLevelAndEachPropsOwnLevel) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    model::SkinnedModel body = model::makeSoldier(1, false);
    model::buildLods(body);
    const model::PropMesh rifle = model::makeRifle(), flag = model::makeFlag();
    ASSERT_EQ(soldier.props.size(), 2u);
    for (std::size_t l = 0; l < model::kLodLevels; ++l) {
        // The body's level is the soldier's without props; the props add exactly their own level.
        EXPECT_EQ(soldier.lods[l].indices.size() / 3, body.lods[l].indices.size() / 3 + rifle.triangleCount(l) + flag.triangleCount(l))
            << "level " << l;
        if (l > 0) {
            EXPECT_EQ(soldier.lods[l].vertexCount, body.lods[l].vertexCount + distinctVertices(rifle.levels[l]) +
                                                       distinctVertices(flag.levels[l]))
                << "level " << l;
        }
        // Each prop's triangles at that level are its own level's, where its joint and offset put them.
        EXPECT_EQ(propTrianglesAtLevel(soldier, soldier.props[0].joint, l), meshTrianglesAtLevel(rifle, l)) << "rifle, level " << l;
        EXPECT_EQ(propTrianglesAtLevel(soldier, soldier.props[1].joint, l), meshTrianglesAtLevel(flag, l)) << "flag, level " << l;
    }
    // The rifle's and flag's coarser levels reuse level 0's vertices: level 0 skins no more than before.
    EXPECT_EQ(soldier.lods[0].vertexCount, body.lods[0].vertexCount + rifle.vertices.size() + flag.vertices.size());
    // Level 2 (docs/props.md#cost): 322 triangles and 336 vertices, against 318 and 417 when the props
    // were simplified with the body (their flat-shaded boxes kept nearly every corner).
    EXPECT_EQ(soldier.lods[2].indices.size() / 3, 322u);
    EXPECT_EQ(soldier.lods[2].vertexCount, 336u);
}

TEST(Props, APropWithAnEmptyLevelIsNotDrawnThereAndLevelsMustNest) {
    model::SkinnedModel body = model::makeSoldier(1, false);
    model::buildLods(body);
    model::PropMesh rifle = model::makeRifle();
    rifle.levels[2].clear();
    model::SkinnedModel carrying = model::makeSoldier(1, false);
    model::attachProp(carrying, rifle, "hand_r", testOffset());
    model::buildLods(carrying);
    const std::uint32_t joint = carrying.props[0].joint;
    EXPECT_TRUE(propTrianglesAtLevel(carrying, joint, 2).empty());
    EXPECT_EQ(carrying.lods[2].vertexCount, body.lods[2].vertexCount);  // not even skinned at level 2
    EXPECT_EQ(propTrianglesAtLevel(carrying, joint, 1), meshTrianglesAtLevel(rifle, 1));
    // Attached again over a model whose levels are built (what Model::withProps does): the same levels.
    model::attachProp(carrying, model::makeFlag(), "head", testOffset());
    model::buildLods(carrying);
    EXPECT_TRUE(propTrianglesAtLevel(carrying, joint, 2).empty());
    EXPECT_EQ(propTrianglesAtLevel(carrying, joint, 1), meshTrianglesAtLevel(rifle, 1));
    EXPECT_EQ(propTrianglesAtLevel(carrying, carrying.props[1].joint, 2), meshTrianglesAtLevel(model::makeFlag(), 2));

    // A coarser level on a vertex the level above does not use would break the vertex prefixes.
    model::PropMesh loose = model::makeRifle();
    loose.levels[1] = {loose.levels[0][0], loose.levels[0][1], loose.levels[0][2]};
    model::SkinnedModel other = model::makeSoldier(1, false);
    try {
        model::attachProp(other, loose, "hand_r", glm::mat4(1.0f));
        FAIL() << "a level-2 triangle over vertices level 1 does not use was accepted";
    } catch (const gpu::Error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("level 2 uses a vertex level 1 does not"), std::string::npos) << message;
        EXPECT_NE(message.find("'rifle'"), std::string::npos) << message;
    }
    model::PropMesh empty = model::makeFlag();
    empty.levels[0].clear();
    EXPECT_THROW(model::attachProp(other, empty, "hand_l", glm::mat4(1.0f)), gpu::Error);
}

TEST(Props, AMissingJointIsOneErrorNamingTheModelAndTheJoint) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier();
    crowdgpu::PropAttachment tail{crowdgpu::Prop::rifle(), "tail"};
    try {
        soldier.withProps({tail});
        FAIL() << "a prop on a missing joint was accepted";
    } catch (const crowdgpu::Error& error) {
        EXPECT_EQ(error.code(), crowdgpu::ErrorCode::InvalidArgument);
        const std::string message = error.what();
        EXPECT_NE(message.find("soldier"), std::string::npos) << message;
        EXPECT_NE(message.find("'tail'"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    crowdgpu::PropAttachment sheared{crowdgpu::Prop::flag(), "hand_l"};
    sheared.offset[1] = 0.5f;  // shear: normals would be wrong
    EXPECT_THROW(soldier.withProps({sheared}), crowdgpu::Error);
    // A good one: a joint more, named after the prop, and the triangles of the prop.
    const crowdgpu::Model carrying = soldier.withProps({{crowdgpu::Prop::flag(), "head"}});
    EXPECT_EQ(carrying.jointCount(), soldier.jointCount() + 1);
    EXPECT_EQ(carrying.triangleCount(), soldier.triangleCount() + crowdgpu::Prop::flag().triangleCount());
    EXPECT_EQ(carrying.propCount(), soldier.propCount() + 1);
    EXPECT_EQ(carrying.jointName(carrying.propJoint(carrying.propCount() - 1)), "flag_2");  // "flag" is taken
}

TEST(Props, TheCApiRefusesAMissingJointInOneLine) {
    crowdgpu_model soldier = nullptr, carrying = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_model_with_prop(soldier, "flag", "tail", nullptr, 1.0f, &carrying), CROWDGPU_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(carrying, nullptr);
    const std::string message = crowdgpu_last_error();
    EXPECT_NE(message.find("'tail'"), std::string::npos) << message;
    EXPECT_NE(message.find("soldier"), std::string::npos) << message;
    EXPECT_EQ(crowdgpu_model_with_prop(soldier, "banana", "head", nullptr, 1.0f, &carrying), CROWDGPU_ERROR_INVALID_ARGUMENT);
    ASSERT_EQ(crowdgpu_model_with_prop(soldier, "flag", "head", nullptr, 0.5f, &carrying), CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_model_find_joint(carrying, "flag_2"), crowdgpu_model_find_joint(soldier, "flag") + 1);
    crowdgpu_model_destroy(carrying);
    crowdgpu_model_destroy(soldier);
}

TEST(Props, OneSoldierInEightCarriesAFlagByTheSeedAndEveryOneARifle) {
    const model::SkinnedModel soldier = model::makeSoldier(1);
    ASSERT_EQ(soldier.props.size(), 2u);
    EXPECT_EQ(soldier.props[0].name, "rifle");
    EXPECT_EQ(soldier.props[1].name, "flag");
    std::uint32_t flags = 0;
    const std::uint32_t count = 8000;
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t carried = model::defaultPropsCarried(soldier, 7, i);
        EXPECT_EQ(carried & 1u, 1u);
        flags += carried >> 1 & 1u;
        EXPECT_EQ(carried, model::defaultPropsCarried(soldier, 7, i)) << "deterministic";
    }
    // 1,000 expected; a binomial's standard deviation is about 30.
    EXPECT_NEAR(static_cast<double>(flags), count / 8.0, 120.0);
    EXPECT_NE(model::defaultPropsCarried(soldier, 7, 3) >> 1, 2u);  // bits past the model's props stay clear
}

namespace {

struct PropShot {
    app::Rgba8Image image;
    glm::mat4 viewProjection;
};

// One soldier carrying `props`, standing in front of a camera at its left (the flag's side), no shadows
// (a prop's shadow would fall outside its own projection).
PropShot renderCarrying(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, std::uint32_t props,
                        skin::Method method, float time) {
    crowd::Character c;
    c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
    c.props = props;
    crowd::Crowd crowd(soldier, {c});
    test::RendererOptions options;
    options.size = {160, 120};
    options.method = method;
    options.shadows = false;
    test::TestRenderer renderer(context, crowd, options);
    renderer.camera.eye = {2.6f, 1.6f, 2.2f};
    renderer.camera.target = {0.0f, 1.0f, 0.0f};
    renderer.renderFrame(time);
    return {renderer.readback(), test::internalCamera(renderer.camera).viewProjection(160.0f / 120.0f)};
}

// Pixels (row-major, as the image) covered by the CPU projection of the triangles whose vertices all
// belong to joint `joint`, grown by one pixel (edges rasterize either way).
std::vector<bool> projectedCover(const model::SkinnedModel& m, const std::vector<skin::CpuSkinnedVertex>& posed,
                                 std::uint32_t joint, const glm::mat4& viewProjection, int width, int height) {
    std::vector<bool> cover(static_cast<std::size_t>(width * height), false);
    auto pixel = [&](const glm::dvec3& p) {
        const glm::vec4 clip = viewProjection * glm::vec4(glm::vec3(p), 1.0f);
        return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * width, (clip.y / clip.w * 0.5f + 0.5f) * height);
    };
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        if (m.vertices[a].joints.x != joint || m.vertices[b].joints.x != joint || m.vertices[c].joints.x != joint) continue;
        const glm::vec2 p0 = pixel(posed[a].position), p1 = pixel(posed[b].position), p2 = pixel(posed[c].position);
        auto edge = [](glm::vec2 u, glm::vec2 v, glm::vec2 q) { return (v.x - u.x) * (q.y - u.y) - (v.y - u.y) * (q.x - u.x); };
        const float area = edge(p0, p1, p2);
        if (area == 0.0f) continue;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::vec2 q(x + 0.5f, y + 0.5f);
                const float w0 = edge(p1, p2, q) / area, w1 = edge(p2, p0, q) / area, w2 = edge(p0, p1, q) / area;
                if (w0 >= 0 && w1 >= 0 && w2 >= 0) cover[static_cast<std::size_t>(y * width + x)] = true;
            }
    }
    std::vector<bool> grown = cover;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (cover[static_cast<std::size_t>(y * width + x)])
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int u = x + dx, v = y + dy;
                        if (u >= 0 && v >= 0 && u < width && v < height) grown[static_cast<std::size_t>(v * width + u)] = true;
                    }
    return grown;
}

}  // namespace

TEST_F(GpuTest, APropsPixelsAppearWhereItsCpuProjectionFallsAndVanishWhenNotCarried) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const std::uint32_t flagJoint = soldier.props[1].joint;
    const float time = 0.3f;
    // Where the CPU puts the flag: the crowd's CPU bones, skinned by the CPU reference.
    crowd::Character c;
    c.clip = static_cast<std::uint32_t>(soldier.findClip("walk"));
    c.props = 0x3u;
    crowd::Crowd reference(soldier, {c});
    std::vector<gpu::BoneRows> bones(soldier.skeleton.jointCount());
    reference.animateCharacter(0, time, bones);
    const std::vector<skin::CpuSkinnedVertex> posed = skin::skinOnCpu(soldier, bones);
    for (skin::Method method : skin::allMethods()) {
        const PropShot with = renderCarrying(*context, soldier, 0x3u, method, time);
        const PropShot without = renderCarrying(*context, soldier, 0x1u, method, time);
        const int w = static_cast<int>(with.image.width), h = static_cast<int>(with.image.height);
        const std::vector<bool> cover = projectedCover(soldier, posed, flagJoint, with.viewProjection, w, h);
        std::size_t differing = 0, inside = 0, covered = 0;
        for (std::size_t i = 0; i < cover.size(); ++i) {
            bool differs = false;
            for (int ch = 0; ch < 3; ++ch)
                differs = differs || std::abs(int(with.image.pixels[4 * i + ch]) - int(without.image.pixels[4 * i + ch])) > 8;
            differing += differs;
            inside += differs && cover[i];
            covered += cover[i];
        }
        // The flag shows (a 2 m pole and its cloth at this distance: hundreds of pixels), only inside its
        // projection (the image is stored top row first; the projection's y is flipped the same way).
        EXPECT_GT(differing, 150u) << skin::methodName(method);
        EXPECT_GE(static_cast<double>(inside), 0.98 * static_cast<double>(differing)) << skin::methodName(method);
        EXPECT_GE(static_cast<double>(differing), 0.4 * static_cast<double>(covered)) << skin::methodName(method);
    }
}

// ---- Props from glTF files ------------------------------------------------------------------------

namespace {

// A box 0.1 x 0.2 x 0.4 m centred off its origin at (0, 0.1, 0.05), flat-shaded (24 vertices), in two
// primitives: its four long sides in red (material 0) and its two ends in blue (material 1). No skin,
// no node: a static mesh.
struct GltfBox {
    static constexpr glm::vec3 center{0.0f, 0.1f, 0.05f}, half{0.05f, 0.1f, 0.2f};
    std::vector<glm::vec3> corners;  // every vertex, as written
    test::GltfBuilder b;
    GltfBox() {
        nlohmann::json primitives = nlohmann::json::array();
        for (int part = 0; part < 2; ++part) {
            std::vector<float> positions, normals;
            std::vector<std::uint16_t> indices;
            for (int axis : part == 0 ? std::vector<int>{0, 1} : std::vector<int>{2}) {
                for (float sign : {1.0f, -1.0f}) {
                    glm::vec3 n(0.0f);
                    n[axis] = sign;
                    const glm::vec3 u = glm::vec3(n.y != 0.0f || n.z != 0.0f ? 1.0f : 0.0f, n.x != 0.0f ? 1.0f : 0.0f, 0.0f);
                    const glm::vec3 w = glm::cross(n, u);  // (u, w, n) right-handed: corners counter-clockwise from n
                    const auto first = static_cast<std::uint16_t>(positions.size() / 3);
                    for (glm::vec2 ab : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                        const glm::vec3 p = center + half * (n + ab.x * u + ab.y * w);
                        corners.push_back(p);
                        positions.insert(positions.end(), {p.x, p.y, p.z});
                        normals.insert(normals.end(), {n.x, n.y, n.z});
                    }
                    for (std::uint16_t i : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<std::uint16_t>(first + i));
                }
            }
            primitives.push_back({{"attributes", {{"POSITION", b.floats(positions, "VEC3")}, {"NORMAL", b.floats(normals, "VEC3")}}},
                                  {"indices", b.shorts(indices, "SCALAR")},
                                  {"material", part}});
        }
        b.doc["meshes"] = {{{"primitives", primitives}}};
        b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.1, 1.0}}}}},
                              {{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.8, 1.0}}}}}};
    }
};

std::vector<std::uint8_t> textBytes(const std::string& text) { return {text.begin(), text.end()}; }

// A folder of this process's own under the temporary directory (test binaries may run side by side).
std::filesystem::path scratchFolder() {
    return std::filesystem::temp_directory_path() / ("crowd-gltf-props-" + std::to_string(::getpid()));
}

// A file in that folder.
std::filesystem::path writeFile(const std::string& name, const std::vector<std::uint8_t>& bytes) {
    const std::filesystem::path folder = scratchFolder();
    std::filesystem::create_directories(folder);
    const std::filesystem::path path = folder / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return path;
}

}  // namespace

TEST(Props, AGltfMeshIsARigidPropWithItsPositionsNormalsColoursAndLevels) {
    GltfBox box;
    const std::filesystem::path path = writeFile("box.glb", box.b.glb());
    const model::PropMesh prop = model::loadGltfProp(path);
    EXPECT_EQ(prop.name, "box");
    ASSERT_EQ(prop.vertices.size(), 24u);
    EXPECT_EQ(prop.triangleCount(0), 12u);  // both primitives
    ASSERT_EQ(prop.materialColors.size(), 2u);
    EXPECT_EQ(prop.materialColors[0], glm::vec4(0.8f, 0.2f, 0.1f, 1.0f));
    EXPECT_EQ(prop.materialColors[1], glm::vec4(0.1f, 0.2f, 0.8f, 1.0f));
    std::multiset<std::array<float, 3>> written, read;
    for (const glm::vec3& p : box.corners) written.insert({p.x, p.y, p.z});
    for (const gpu::SkinVertex& v : prop.vertices) {
        read.insert({v.position.x, v.position.y, v.position.z});
        // The ends (normal along z) are the second primitive's: blue; the sides red.
        EXPECT_EQ(v.normal.w, std::abs(v.normal.z) == 1.0f ? 1.0f : 0.0f);
        EXPECT_EQ(v.joints.x, 0u);
        EXPECT_EQ(v.weights.x, 1.0f);
    }
    EXPECT_EQ(read, written);  // every vertex where the file put it, in the mesh's own space
    // Levels made as a model's, by meshoptimizer (within its budgets: 6 and 3 triangles of 12, when it
    // can), never empty, nested.
    for (std::size_t l = 1; l < model::kLodLevels; ++l) {
        EXPECT_GT(prop.triangleCount(l), 0u) << "level " << l;
        EXPECT_LE(prop.triangleCount(l), prop.triangleCount(l - 1)) << "level " << l;
    }
    EXPECT_LT(prop.triangleCount(2), 12u);
    EXPECT_NO_THROW(model::checkPropMesh(prop, "box"));

    // The public API: the same prop, attached as any.
    const crowdgpu::Prop gltfBox = crowdgpu::Prop::fromGltf(path.string());
    EXPECT_EQ(gltfBox.name(), "box");
    EXPECT_EQ(gltfBox.triangleCount(), 12u);
    EXPECT_EQ(gltfBox.lodTriangles(2), prop.triangleCount(2));
    const crowdgpu::Model soldier = crowdgpu::Model::soldier();
    const crowdgpu::Model carrying = soldier.withProps({{gltfBox, "hand_r"}});
    EXPECT_EQ(carrying.triangleCount(), soldier.triangleCount() + 12u);
    EXPECT_EQ(carrying.jointName(carrying.propJoint(carrying.propCount() - 1)), "box");
}

TEST_F(GpuTest, AGltfPropOnTheHandSkinsToJointWorldTimesOffsetTimesLocalAtEveryLevel) {
    GltfBox box;
    const model::PropMesh prop = model::loadGltfProp(writeFile("box.gltf", textBytes(box.b.gltf())));
    model::SkinnedModel m = model::makeSoldier(1);
    model::attachProp(m, prop, "hand_l", testOffset());
    const std::uint32_t propJoint = m.props.back().joint, hand = m.props.back().attachedTo;
    model::buildLods(m);
    m.poseSphere = crowd::computePoseSphere(m);
    const std::size_t checked = expectPropAtJointTimesOffsetAtEveryLevel(*context, m, propJoint, hand, testOffset(),
                                                                        {skin::Method::Compute, skin::Method::TwoPass});
    EXPECT_GE(checked, 2u * 4u * 24u);  // level 0 alone: two methods, four characters, the box's 24 vertices
}

TEST(Props, ABadGltfPropIsOneLineNamingTheFileAndTheProblem) {
    auto expectRefused = [](const std::filesystem::path& path, const std::string& problem) {
        try {
            crowdgpu::Prop::fromGltf(path.string());
            ADD_FAILURE() << path << " was accepted";
        } catch (const crowdgpu::Error& error) {
            EXPECT_EQ(error.code(), crowdgpu::ErrorCode::LoadFailed);
            const std::string message = error.what();
            EXPECT_NE(message.find(path.string()), std::string::npos) << message;
            EXPECT_NE(message.find(problem), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    };
    expectRefused(scratchFolder() / "absent.glb", "no such file");
    GltfBox box;
    box.b.doc["meshes"][0]["primitives"][1]["indices"] = 99;  // an accessor the file does not have
    expectRefused(writeFile("bad-index.gltf", textBytes(box.b.gltf())),
                  "accessor");
    GltfBox noMesh;
    noMesh.b.doc.erase("meshes");
    expectRefused(writeFile("no-mesh.gltf", textBytes(noMesh.b.gltf())),
                  "no mesh");
    expectRefused(writeFile("garbage.glb", {'g', 'l', 'T', 'F', 2, 0, 0, 0}), "garbage.glb");
}

TEST(Props, TheCApiAttachesAGltfPropAndRefusesABadFileInOneLine) {
    GltfBox box;
    const std::filesystem::path path = writeFile("c-box.glb", box.b.glb());
    crowdgpu_model soldier = nullptr, carrying = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    ASSERT_EQ(crowdgpu_model_with_gltf_prop(soldier, path.string().c_str(), nullptr, "hand_r", nullptr, 1.0f, &carrying),
              CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_model_find_joint(carrying, "c-box"), crowdgpu_model_find_joint(soldier, "flag") + 1);
    crowdgpu_model_destroy(carrying);
    carrying = nullptr;
    const std::string absent = (scratchFolder() / "absent.gltf").string();
    EXPECT_EQ(crowdgpu_model_with_gltf_prop(soldier, absent.c_str(), nullptr, "hand_r", nullptr, 1.0f, &carrying),
              CROWDGPU_ERROR_LOAD_FAILED);
    EXPECT_EQ(carrying, nullptr);
    const std::string message = crowdgpu_last_error();
    EXPECT_NE(message.find(absent + ": no such file"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    crowdgpu_model_destroy(soldier);
}
