// The glTF loader on small hand-built characters: what each supported feature turns into, checked
// against hand-computed answers.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <unistd.h>

#include "support/gpu_test.h"
#include "app/error.h"
#include "skin/cpu_skinning.h"
#include "app/crowd_app.h"
#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "support/gltf_builder.h"

namespace {

using test::GltfBuilder;

constexpr double kExact = 1e-6;  // float arithmetic on numbers of order 1

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance, const std::string& what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

std::vector<skin::CpuSkinnedVertex> pose(const model::SkinnedModel& m, const std::string& clip, float time) {
    return skin::poseOnCpu(m, test::clipIndex(m, clip), time);
}

}  // namespace

TEST(GltfLoader, StripCharacterLoadsWithSkeletonMaterialsAndClip) {
    const model::SkinnedModel m = test::loadText(test::stripCharacter().gltf());
    EXPECT_EQ(m.name, "test.gltf");
    ASSERT_EQ(m.skeleton.jointCount(), 2u);
    EXPECT_EQ(m.skeleton.jointNames, (std::vector<std::string>{"root", "tip"}));
    EXPECT_EQ(m.skeleton.parents, (std::vector<std::int32_t>{-1, 0}));
    // "world" is static, not a joint, and above every joint: it folds into the root transform.
    EXPECT_EQ(m.skeleton.rootTransform, glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)));
    EXPECT_EQ(m.vertices.size(), 6u);
    EXPECT_EQ(m.triangleCount(), 4u);
    ASSERT_EQ(m.materialColors.size(), 1u);
    EXPECT_EQ(m.materialColors[0], glm::vec4(0.8f, 0.2f, 0.1f, 1.0f));
    ASSERT_EQ(m.clips.size(), 1u);
    EXPECT_EQ(m.clips[0].name, "bend");
    EXPECT_FLOAT_EQ(m.clips[0].duration, 1.0f);
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.baseColorTexture.rgba.empty());
}

TEST(GltfLoader, BoundsAreTheRestPoseInWorldAndIgnoreTheMeshNodeTransform) {
    // The body node's translation (5, 5, 5) must not move a skinned mesh; "world" moves it by +2 in x.
    const model::SkinnedModel m = test::loadText(test::stripCharacter().gltf());
    EXPECT_EQ(m.boundsMin, glm::vec3(1.5f, 0.0f, 0.0f));
    EXPECT_EQ(m.boundsMax, glm::vec3(2.5f, 2.0f, 0.0f));
    EXPECT_FLOAT_EQ(m.height(), 2.0f);
}

TEST(GltfLoader, RestPoseSkinningReproducesBindPositionsAfterRootTransform) {
    const model::SkinnedModel m = test::loadText(test::stripCharacter().gltf());
    // At t = 0 the bend clip holds the rest rotation, so skinning gives back the bind positions.
    const std::vector<skin::CpuSkinnedVertex> posed = pose(m, "bend", 0.0f);
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        expectNear(posed[v].position, glm::dvec3(m.vertices[v].position) + glm::dvec3(2, 0, 0), kExact,
                   "vertex " + std::to_string(v));
        expectNear(posed[v].normal, glm::dvec3(0, 0, 1), kExact, "normal " + std::to_string(v));
    }
}

TEST(GltfLoader, LinearRotationBendsTheTopRowAboutTheTip) {
    const model::SkinnedModel m = test::loadText(test::stripCharacter().gltf());
    // The tip sits at (2, 1, 0). At t = 1 it has turned 90 degrees about z: the top-left vertex,
    // (-0.5, 1, 0) from the tip, goes to (-1, -0.5, 0) from it.
    std::vector<skin::CpuSkinnedVertex> posed = pose(m, "bend", 1.0f - 1e-6f);
    expectNear(posed[4].position, {1.0, 0.5, 0.0}, 1e-5, "top-left at 90 degrees");
    expectNear(posed[5].position, {1.0, 1.5, 0.0}, 1e-5, "top-right at 90 degrees");
    // At t = 0.25, a quarter of the way by slerp: 22.5 degrees.
    posed = pose(m, "bend", 0.25f);
    const double a = glm::radians(22.5);
    expectNear(posed[4].position, {2.0 - 0.5 * std::cos(a) - std::sin(a), 1.0 - 0.5 * std::sin(a) + std::cos(a), 0.0},
               1e-5, "top-left at 22.5 degrees");
    // The bottom row follows the root alone and does not move.
    expectNear(posed[0].position, {1.5, 0.0, 0.0}, kExact, "bottom-left");
}

TEST(GltfLoader, StepAndCubicSplineChannelsFollowTheSpecification) {
    // STEP: the root jumps up by 1 m at t = 1 and holds its first key until then. CUBICSPLINE, zero
    // tangents: the tip's scale eases from 1 to 3; at the midpoint it is 2.
    GltfBuilder b = test::stripCharacter();
    test::addHopAnimation(b);
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.clips.size(), 2u);
    EXPECT_EQ(m.clips[1].channels[0].interpolation, anim::Interpolation::Step);
    EXPECT_EQ(m.clips[1].channels[1].interpolation, anim::Interpolation::CubicSpline);
    const std::vector<skin::CpuSkinnedVertex> posed = pose(m, "hop", 0.5f);
    expectNear(posed[0].position, {1.5, 0.0, 0.0}, kExact, "STEP holds the first key");
    // Top-left: (-0.5, 1, 0) from the tip, scaled by 2.
    expectNear(posed[4].position, {1.0, 3.0, 0.0}, 1e-5, "CUBICSPLINE midpoint");
}

TEST(GltfLoader, UnnamedClipsAreNumberedAndClipsResolveByNameOrIndex) {
    GltfBuilder b = test::stripCharacter();
    nlohmann::json unnamed = b.doc["animations"][0];
    unnamed.erase("name");
    b.doc["animations"].push_back(unnamed);
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.clips.size(), 2u);
    EXPECT_EQ(m.clips[1].name, "clip1");
    EXPECT_EQ(test::clipIndex(m, "clip1"), 1u);
    EXPECT_EQ(test::clipIndex(m, "bend"), 0u);
    EXPECT_EQ(test::clipIndex(m, "1"), 1u);
    EXPECT_THROW(test::clipIndex(m, "moonwalk"), app::Error);
}

TEST(GltfLoader, JointsAreReorderedSoParentsComeFirst) {
    // Skin lists the tip before the root, and the tip's node comes before the root's.
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"] = {{{"name", "world"}, {"children", {2, 3}}, {"translation", {2, 0, 0}}},
                      {{"name", "tip"}, {"translation", {0, 1, 0}}},
                      {{"name", "root"}, {"children", {1}}},
                      {{"name", "body"}, {"mesh", 0}, {"skin", 0}}};
    // Skin joint 0 is now the tip: swap the inverse bind matrices and the vertices' joint numbers.
    b.doc["skins"][0]["joints"] = {1, 2};
    b.doc["skins"][0]["inverseBindMatrices"] = b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1,  //
                                                         1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1},
                                                        "MAT4");
    test::stripPrimitive(b)["attributes"]["JOINTS_0"] =
        b.shorts({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC4");
    b.doc["animations"][0]["channels"][0]["target"]["node"] = 1;
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.skeleton.jointNames, (std::vector<std::string>{"root", "tip"}));
    EXPECT_EQ(m.skeleton.parents, (std::vector<std::int32_t>{-1, 0}));
    EXPECT_EQ(m.vertices[0].joints.x, 0u) << "bottom row follows the root";
    EXPECT_EQ(m.vertices[4].joints.x, 1u) << "top row follows the tip";
    EXPECT_EQ(m.clips[0].channels[0].joint, 1u);
    expectNear(pose(m, "bend", 1.0f - 1e-6f)[4].position, {1.0, 0.5, 0.0}, 1e-5, "same bend as before");
}

TEST(GltfLoader, MissingInverseBindMatricesAreIdentity) {
    GltfBuilder b = test::stripCharacter();
    b.doc["skins"][0].erase("inverseBindMatrices");
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.skeleton.inverseBind[1], glm::mat4(1.0f));
    // The tip's vertices now move by the tip's offset (0, 1, 0) as well.
    EXPECT_FLOAT_EQ(m.boundsMax.y, 3.0f);
}

TEST(GltfLoader, NodeBetweenJointsBecomesAJoint) {
    // root -> elbow (not in the skin, lifts by 0.5) -> tip: the elbow's transform must count.
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"][1]["children"] = {4};
    b.doc["nodes"].push_back({{"name", "elbow"}, {"children", {2}}, {"translation", {0, 0.5, 0}}});
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.skeleton.jointNames, (std::vector<std::string>{"root", "elbow", "tip"}));
    EXPECT_EQ(m.skeleton.parents, (std::vector<std::int32_t>{-1, 0, 1}));
    EXPECT_FLOAT_EQ(m.boundsMax.y, 2.5f);
}

TEST(GltfLoader, AnimatedNodeAboveTheSkeletonStaysAJoint) {
    GltfBuilder b = test::stripCharacter();
    const int times = b.floats({0.0f, 1.0f}, "SCALAR");
    const int moves = b.floats({2, 0, 0, 2, 0, 4}, "VEC3");
    b.doc["animations"][0]["samplers"].push_back({{"input", times}, {"output", moves}});
    b.doc["animations"][0]["channels"].push_back({{"sampler", 1}, {"target", {{"node", 0}, {"path", "translation"}}}});
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.skeleton.jointNames, (std::vector<std::string>{"world", "root", "tip"}));
    EXPECT_EQ(m.skeleton.rootTransform, glm::mat4(1.0f));
    expectNear(pose(m, "bend", 0.5f)[0].position, {1.5, 0.0, 2.0}, 1e-5, "the world node walks along z");
}

TEST(GltfLoader, ChannelsOnNodesOutsideTheSkeletonAreIgnored) {
    GltfBuilder b = test::stripCharacter();
    b.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", 3}, {"path", "rotation"}}}});
    std::vector<std::string> notes;
    const model::SkinnedModel m = test::loadText(b.gltf(), &notes);
    EXPECT_EQ(m.clips[0].channels.size(), 1u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("outside the skeleton"), std::string::npos) << notes[0];
}

TEST(GltfLoader, ZeroLengthClipIsAStaticPose) {
    GltfBuilder b = test::stripCharacter();
    const std::vector<float> q = test::quatZ(90.0f);
    b.doc["animations"] = {{{"name", "pose"},
                            {"samplers", {{{"input", b.floats({0.0f}, "SCALAR")}, {"output", b.floats(q, "VEC4")}}}},
                            {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}}}}}};
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.clips[0].duration, 0.0f);
    for (float t : {0.0f, 0.7f, 12.0f}) expectNear(pose(m, "pose", t)[4].position, {1.0, 0.5, 0.0}, 1e-5, "any time");
}

TEST(GltfLoader, FileWithoutAnimationsStandsInARestClip) {
    GltfBuilder b = test::stripCharacter();
    b.doc.erase("animations");
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.clips.size(), 1u);
    EXPECT_EQ(m.clips[0].name, "rest");
    EXPECT_EQ(m.clips[0].duration, 0.0f);
}

TEST(GltfLoader, ByteAndShortJointsAndNormalizedWeightsLoad) {
    GltfBuilder b = test::stripCharacter();
    auto& attributes = test::stripPrimitive(b)["attributes"];
    attributes["JOINTS_0"] = b.bytes({0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    attributes["WEIGHTS_0"] =
        b.bytes({255, 0, 0, 0, 255, 0, 0, 0, 64, 191, 0, 0, 64, 191, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0}, "VEC4", true);
    model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.vertices[2].joints, glm::uvec4(1, 0, 0, 0)) << "largest weight first";
    EXPECT_NEAR(m.vertices[2].weights.x, 191.0 / 255.0, 1e-6);
    EXPECT_NEAR(m.vertices[2].weights.y, 64.0 / 255.0, 1e-6);

    attributes["WEIGHTS_0"] = b.shorts({65535, 0, 0, 0, 65535, 0, 0, 0, 16384, 49151, 0, 0, 16384, 49151, 0, 0,  //
                                        65535, 0, 0, 0, 65535, 0, 0, 0},
                                       "VEC4", true);
    m = test::loadText(b.gltf());
    EXPECT_NEAR(m.vertices[3].weights.x, 49151.0 / 65535.0, 1e-6);
    EXPECT_NEAR(m.vertices[3].weights.x + m.vertices[3].weights.y, 1.0, 1e-6);
}

TEST(GltfLoader, MoreThanFourInfluencesKeepTheLargestFourRenormalized) {
    // A chain of six joints; vertex 0 has six influences over JOINTS_0/1.
    GltfBuilder b = test::stripCharacter();
    b.doc["nodes"] = {{{"name", "j0"}, {"children", {1}}},         {{"name", "j1"}, {"children", {2}}},
                      {{"name", "j2"}, {"children", {3}}},         {{"name", "j3"}, {"children", {4}}},
                      {{"name", "j4"}, {"children", {5}}},         {{"name", "j5"}},
                      {{"name", "body"}, {"mesh", 0}, {"skin", 0}}};
    b.doc["skins"][0] = {{"joints", {0, 1, 2, 3, 4, 5}}};
    b.doc["scenes"][0]["nodes"] = {0, 6};
    b.doc.erase("animations");
    auto& attributes = test::stripPrimitive(b)["attributes"];
    std::vector<std::uint16_t> joints0(24, 0), joints1(24, 0);
    std::vector<float> weights0(24, 0.0f), weights1(24, 0.0f);
    for (int v = 0; v < 6; ++v) weights0[static_cast<std::size_t>(v * 4)] = 1.0f;
    joints0 = {0, 1, 2, 3};
    joints0.resize(24, 0);
    weights0[0] = 0.3f, weights0[1] = 0.05f, weights0[2] = 0.2f, weights0[3] = 0.1f;
    joints1[0] = 4, joints1[1] = 5;
    weights1[0] = 0.25f, weights1[1] = 0.1f;
    attributes["JOINTS_0"] = b.shorts(joints0, "VEC4");
    attributes["WEIGHTS_0"] = b.floats(weights0, "VEC4");
    attributes["JOINTS_1"] = b.shorts(joints1, "VEC4");
    attributes["WEIGHTS_1"] = b.floats(weights1, "VEC4");
    const model::SkinnedModel m = test::loadText(b.gltf());
    // Kept: 0.3 (j0), 0.25 (j4), 0.2 (j2), 0.1 (j3, the first of the two 0.1s); dropped 0.1 (j5), 0.05 (j1).
    EXPECT_EQ(m.vertices[0].joints, glm::uvec4(0, 4, 2, 3));
    const glm::vec4 expected = glm::vec4(0.3f, 0.25f, 0.2f, 0.1f) / 0.85f;
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(m.vertices[0].weights[k], expected[k], 1e-6) << k;
}

TEST(GltfLoader, NonIndexedPrimitiveGetsAnIndexBuffer) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b).erase("indices");
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(GltfLoader, StripsAndFansBecomeTriangleLists) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["mode"] = 5;  // TRIANGLE_STRIP
    test::stripPrimitive(b)["indices"] = b.shorts({0, 1, 2, 3, 4, 5}, "SCALAR");
    model::SkinnedModel m = test::loadText(b.gltf());
    // glTF: strip triangle i is {i, i + 1 + i % 2, i + 2 - i % 2}.
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4}));
    test::stripPrimitive(b)["mode"] = 6;  // TRIANGLE_FAN: {i + 1, i + 2, 0}
    m = test::loadText(b.gltf());
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0}));
}

TEST(GltfLoader, MissingNormalsAreAreaWeightedFaceNormals) {
    // Vertex 0 at the origin is shared by a triangle in the xy plane of area 2 (normal +z) and one in
    // the yz plane of area 1 (normal +x): its normal is (1, 0, 2) / sqrt(5).
    GltfBuilder b = test::stripCharacter();
    auto& primitive = test::stripPrimitive(b);
    primitive["attributes"]["POSITION"] = b.floats({0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 0, 0, 0}, "VEC3");
    primitive["attributes"].erase("NORMAL");
    primitive["indices"] = b.shorts({0, 1, 2, 0, 4, 3}, "SCALAR");
    const model::SkinnedModel m = test::loadText(b.gltf());
    expectNear(glm::dvec3(m.vertices[0].normal), glm::dvec3(1, 0, 2) / std::sqrt(5.0), kExact, "shared vertex");
    expectNear(glm::dvec3(m.vertices[1].normal), {0, 0, 1}, kExact, "xy triangle only");
    expectNear(glm::dvec3(m.vertices[3].normal), {1, 0, 0}, kExact, "yz triangle only");
    expectNear(glm::dvec3(m.vertices[5].normal), {0, 1, 0}, kExact, "on no triangle: any unit vector");
}

TEST(GltfLoader, SeveralPrimitivesMergeWithOnePaletteEntryPerMaterial) {
    GltfBuilder b = test::stripCharacter();
    nlohmann::json second = test::stripPrimitive(b);
    second["material"] = 1;
    nlohmann::json third = test::stripPrimitive(b);
    third.erase("material");  // glTF's default material: white
    b.doc["meshes"][0]["primitives"].push_back(second);
    b.doc["meshes"][0]["primitives"].push_back(third);
    b.doc["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 1.0, 0.5}}}}});
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(m.vertices.size(), 18u);
    EXPECT_EQ(m.triangleCount(), 12u);
    ASSERT_EQ(m.materialColors.size(), 3u);
    EXPECT_EQ(m.materialColors[1], glm::vec4(0, 0, 1, 0.5f));
    EXPECT_EQ(m.materialColors[2], glm::vec4(1.0f));
    EXPECT_EQ(m.vertices[0].normal.w, 0.0f);
    EXPECT_EQ(m.vertices[6].normal.w, 1.0f);
    EXPECT_EQ(m.vertices[12].normal.w, 2.0f);
    // The second primitive's indices are offset by the first's vertices.
    EXPECT_EQ(m.indices[12], 6u);
}

TEST(GltfLoader, BaseColorTextureAndTexcoordsLoad) {
    GltfBuilder b = test::stripCharacter();
    test::stripPrimitive(b)["attributes"]["TEXCOORD_0"] = b.floats({0, 0, 1, 0, 0, 0.5f, 1, 0.5f, 0, 1, 1, 1}, "VEC2");
    b.doc["images"] = {{{"bufferView", b.view(test::png2x2())}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.uvs.size(), 6u);
    EXPECT_EQ(m.uvs[3], glm::vec2(1.0f, 0.5f));
    EXPECT_EQ(m.baseColorTexture.width, 2u);
    EXPECT_EQ(m.baseColorTexture.height, 2u);
    EXPECT_EQ(m.baseColorTexture.rgba,
              (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}));
    EXPECT_EQ(m.texturedMaterials, 1u);
}

TEST(GltfLoader, UndecodableTextureIsLeftOutWithANote) {
    GltfBuilder b = test::stripCharacter();
    std::vector<std::uint8_t> broken = test::png2x2();
    broken.resize(30);  // header only
    b.doc["images"] = {{{"bufferView", b.view(broken)}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    std::vector<std::string> notes;
    const model::SkinnedModel m = test::loadText(b.gltf(), &notes);
    EXPECT_TRUE(m.baseColorTexture.rgba.empty());
    EXPECT_EQ(m.texturedMaterials, 0u);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("rendering without a texture"), std::string::npos) << notes[0];
}

TEST(GltfLoader, SparseAccessorReplacesListedElements) {
    GltfBuilder b = test::stripCharacter();
    const int positions = test::stripPrimitive(b)["attributes"]["POSITION"];
    nlohmann::json sparse = b.doc["accessors"][static_cast<std::size_t>(positions)];
    const std::vector<float> moved = {-0.5f, 2.5f, 0.0f};
    std::vector<std::uint8_t> raw(12);
    std::memcpy(raw.data(), moved.data(), 12);
    sparse["sparse"] = {{"count", 1},
                        {"indices", {{"bufferView", b.view({4, 0})}, {"componentType", 5123}}},
                        {"values", {{"bufferView", b.view(raw)}}}};
    b.doc["accessors"].push_back(sparse);
    test::stripPrimitive(b)["attributes"]["POSITION"] = b.doc["accessors"].size() - 1;
    const model::SkinnedModel m = test::loadText(b.gltf());
    EXPECT_EQ(glm::vec3(m.vertices[4].position), glm::vec3(-0.5f, 2.5f, 0.0f));
    EXPECT_EQ(glm::vec3(m.vertices[5].position), glm::vec3(0.5f, 2.0f, 0.0f));
}

TEST(GltfLoader, GlbLoadsTheSameAsGltf) {
    const GltfBuilder b = test::stripCharacter();
    const model::SkinnedModel fromText = test::loadText(b.gltf());
    const model::SkinnedModel fromGlb = test::loadBytes(b.glb());
    ASSERT_EQ(fromGlb.vertices.size(), fromText.vertices.size());
    for (std::size_t v = 0; v < fromText.vertices.size(); ++v)
        EXPECT_EQ(fromGlb.vertices[v].position, fromText.vertices[v].position);
    EXPECT_EQ(fromGlb.indices, fromText.indices);
    EXPECT_EQ(fromGlb.clips[0].channels[0].values, fromText.clips[0].channels[0].values);
}

TEST(GltfLoader, ExternalBinFileBesideTheGltfIsRead) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("crowd-gltf-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    GltfBuilder b = test::stripCharacter();
    b.doc["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", "strip%20data.bin"}}};  // URIs are percent-encoded
    std::ofstream(dir / "strip data.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(b.bin.data()), static_cast<std::streamsize>(b.bin.size()));
    std::ofstream(dir / "strip.gltf") << b.gltf(false);
    const model::SkinnedModel m = model::loadGltf(dir / "strip.gltf");
    EXPECT_EQ(m.name, "strip");
    EXPECT_EQ(m.vertices.size(), 6u);
    std::filesystem::remove_all(dir);
}
