// Real skinned characters from ../shared/assets (Fox, CesiumMan, RiggedSimple): their facts from
// INVENTORY.md, poses against glTF skinning evaluated independently from tinygltf's parse, the GPU
// methods against the CPU reference, and crowd-render's --list-clips and --export-pose.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "app/crowd_app.h"
#include "model/gltf_loader.h"
#include "app/crowd_renderer.h"
#include "skin/cpu_skinning.h"
#include "support/gltf_reference.h"
#include "support/gpu_test.h"
#include "support/run_program.h"
#include "support/vertex_matching.h"

namespace {

using test::GpuTest;

struct ClipFact {
    std::string name;
    float duration;  // seconds, as INVENTORY.md rounds them (2 decimals)
};

struct Asset {
    std::string file;  // under ../shared/assets
    std::size_t vertices, triangles, joints;
    std::vector<ClipFact> clips;
    // Whether the nodes' own transforms are the pose the mesh was bound in (the Fox's are not: its
    // nodes hold another pose, and only its inverse bind matrices remember the bind pose).
    bool restIsBind;
};

const Asset kFox{"fox/Fox.glb", 1728, 576, 24, {{"Run", 1.12f}, {"Survey", 3.42f}, {"Walk", 0.71f}}, false};
const Asset kCesiumMan{"cesium-man/CesiumMan.glb", 3273, 4672, 19, {{"clip0", 2.00f}}, true};
const Asset kRiggedSimple{"rigged-simple/RiggedSimple.glb", 960, 892, 4, {{"Anim_0_Armature", 6.67f}}, true};
const std::vector<Asset> kAssets = {kFox, kCesiumMan, kRiggedSimple};

std::filesystem::path assetPath(const Asset& asset) {
    return std::filesystem::path(CROWD_SHARED_ASSETS_DIR) / asset.file;
}

bool haveAsset(const Asset& asset) { return std::filesystem::exists(assetPath(asset)); }

#define SKIP_WITHOUT(asset) \
    if (!haveAsset(asset))  \
    GTEST_SKIP() << "shared asset " << assetPath(asset) << " not present (see ../shared/assets/INVENTORY.md)"

// Largest distance between two lists of points.
double largestDistance(const std::vector<skin::CpuSkinnedVertex>& a, const std::vector<glm::dvec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    double largest = 0.0;
    for (std::size_t v = 0; v < std::min(a.size(), b.size()); ++v)
        largest = std::max(largest, glm::length(a[v].position - b[v]));
    return largest;
}

float extent(const model::SkinnedModel& m) { return glm::length(m.boundsMax - m.boundsMin); }

}  // namespace

TEST(GltfAssets, CountsAndClipsMatchTheInventory) {
    int present = 0;
    for (const Asset& asset : kAssets) {
        if (!haveAsset(asset)) continue;
        ++present;
        const model::SkinnedModel m = model::loadGltf(assetPath(asset));
        EXPECT_EQ(m.vertices.size(), asset.vertices) << asset.file;
        EXPECT_EQ(m.triangleCount(), asset.triangles) << asset.file;
        EXPECT_EQ(m.skeleton.jointCount(), asset.joints) << asset.file;
        ASSERT_EQ(m.clips.size(), asset.clips.size()) << asset.file;
        for (std::size_t c = 0; c < m.clips.size(); ++c) {
            EXPECT_EQ(m.clips[c].name, asset.clips[c].name) << asset.file;
            EXPECT_NEAR(m.clips[c].duration, asset.clips[c].duration, 0.005) << asset.file << " " << m.clips[c].name;
        }
        EXPECT_GT(m.height(), 0.0f) << asset.file;
    }
    if (present == 0) GTEST_SKIP() << "no shared assets in " << CROWD_SHARED_ASSETS_DIR;
}

TEST(GltfAssets, TexturedAssetsCarryTheirTextureAndTexcoords) {
    for (const Asset& asset : {kFox, kCesiumMan}) {
        if (!haveAsset(asset)) continue;
        const model::SkinnedModel m = model::loadGltf(assetPath(asset));
        EXPECT_EQ(m.uvs.size(), m.vertices.size()) << asset.file;
        EXPECT_GT(m.baseColorTexture.width, 0u) << asset.file;
        EXPECT_EQ(m.baseColorTexture.rgba.size(),
                  std::size_t{m.baseColorTexture.width} * m.baseColorTexture.height * 4);
        EXPECT_EQ(m.texturedMaterials, 1u) << asset.file;
    }
    if (!haveAsset(kRiggedSimple)) return;
    EXPECT_TRUE(model::loadGltf(assetPath(kRiggedSimple)).baseColorTexture.rgba.empty());
}

TEST(GltfAssets, RestPoseSkinningReproducesTheBindPositionsAfterTheRootTransform) {
    // CesiumMan and RiggedSimple are bound in their rest pose, so every joint matrix (global * inverse
    // bind) is the transform of the nodes above the skeleton (their mesh nodes hang there too), and
    // skinning the rest pose gives the bind positions moved by it. For every asset the independent
    // evaluation agrees, and the bounds are the rest pose's.
    int present = 0;
    for (const Asset& asset : kAssets) {
        if (!haveAsset(asset)) continue;
        ++present;
        const model::SkinnedModel m = model::loadGltf(assetPath(asset));
        const std::vector<skin::CpuSkinnedVertex> rest =
            skin::poseOnCpu(m, static_cast<std::uint32_t>(m.clips.size()), 0.0f);
        std::vector<glm::dvec3> bind;
        for (const gpu::SkinVertex& v : m.vertices)
            bind.emplace_back(glm::dmat4(m.skeleton.rootTransform) * glm::dvec4(v.position));
        const double tolerance = 1e-5 * extent(m);
        if (asset.restIsBind)
            EXPECT_LE(largestDistance(rest, bind), tolerance) << asset.file;
        else
            EXPECT_GT(largestDistance(rest, bind), 0.1 * m.height()) << asset.file << " is not bound in its rest pose";
        EXPECT_LE(
            largestDistance(rest, test::referenceSkinnedPositions(test::parseWithTinygltf(assetPath(asset)), -1, 0.0)),
            tolerance)
            << asset.file;
        // Bounds are those of the rest pose.
        glm::dvec3 lo(1e30), hi(-1e30);
        for (const skin::CpuSkinnedVertex& v : rest) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        EXPECT_LE(glm::length(lo - glm::dvec3(m.boundsMin)) + glm::length(hi - glm::dvec3(m.boundsMax)), tolerance)
            << asset.file;
    }
    if (present == 0) GTEST_SKIP() << "no shared assets in " << CROWD_SHARED_ASSETS_DIR;
}

TEST(GltfAssets, SampledPosesMatchAnIndependentEvaluationOfTheNodeHierarchy) {
    int present = 0;
    for (const Asset& asset : kAssets) {
        if (!haveAsset(asset)) continue;
        ++present;
        const model::SkinnedModel m = model::loadGltf(assetPath(asset));
        const tinygltf::Model parsed = test::parseWithTinygltf(assetPath(asset));
        for (std::uint32_t c = 0; c < m.clips.size(); ++c) {
            for (const float fraction : {0.1f, 0.37f, 0.8f}) {
                const float time = fraction * m.clips[c].duration;
                const double distance = largestDistance(
                    skin::poseOnCpu(m, c, time), test::referenceSkinnedPositions(parsed, static_cast<int>(c), time));
                // float matrices against double ones: a few ulps of the character's extent.
                EXPECT_LE(distance, 1e-5 * extent(m)) << asset.file << " " << m.clips[c].name << " at " << time << " s";
            }
        }
    }
    if (present == 0) GTEST_SKIP() << "no shared assets in " << CROWD_SHARED_ASSETS_DIR;
}

TEST(GltfAssets, RiggedSimpleAnimationBendsTheCylinder) {
    SKIP_WITHOUT(kRiggedSimple);
    const model::SkinnedModel m = model::loadGltf(assetPath(kRiggedSimple));
    const std::vector<skin::CpuSkinnedVertex> rest = skin::poseOnCpu(m, 1, 0.0f);  // clip 1 does not exist: rest pose
    // The top of the cylinder: the vertex highest in the rest pose.
    std::size_t top = 0;
    for (std::size_t v = 0; v < rest.size(); ++v)
        if (rest[v].position.y > rest[top].position.y) top = v;
    const tinygltf::Model parsed = test::parseWithTinygltf(assetPath(kRiggedSimple));
    double largest = 0.0;
    for (float time = 0.0f; time < m.clips[0].duration; time += 0.25f) {
        const glm::dvec3 posed = skin::poseOnCpu(m, 0, time)[top].position;
        const glm::dvec3 expected = test::referenceSkinnedPositions(parsed, 0, time)[top];
        EXPECT_LE(glm::length(posed - expected), 1e-5 * extent(m)) << "at " << time << " s";
        largest = std::max(largest, glm::length(posed - rest[top].position));
    }
    // The upper bone swings the top well away from where it rests: by more than a tenth of the height.
    EXPECT_GT(largest, 0.1 * m.height());
}

namespace {

// A few characters of a model, each with its own clip, phase and speed.
std::vector<crowd::Character> mixedCharacters(const model::SkinnedModel& model, std::uint32_t count) {
    std::vector<crowd::Character> characters(count);
    const float spacing = 1.5f * std::max(extent(model), 0.1f);
    for (std::uint32_t i = 0; i < count; ++i) {
        crowd::Character& c = characters[i];
        c.clip = i % static_cast<std::uint32_t>(model.clips.size());
        c.timeOffset = 0.137f * static_cast<float>(i);
        c.speed = 0.8f + 0.1f * static_cast<float>(i % 5);
        c.position = glm::vec3(spacing * static_cast<float>(i % 2), 0.0f, spacing * static_cast<float>(i / 2));
        c.heading = 0.4f * static_cast<float>(i);
    }
    return characters;
}

// Largest distance of a method's skinned vertices from the CPU reference, over every character.
double gpuError(const gpu::VulkanContext& context, crowd::Crowd crowd, skin::Method method) {
    const model::SkinnedModel& m = crowd.model(0);
    test::RendererOptions options;
    options.size = {64, 64};
    options.method = method;
    options.cull.mode = render::CullMode::Off;  // every character, at full detail
    options.cull.lod = false;
    test::TestRenderer renderer(context, crowd, options);
    const float time = 0.75f;
    renderer.renderFrame(time);
    renderer.finish();
    double largest = 0.0;
    std::vector<gpu::BoneRows> bones(m.skeleton.jointCount());
    const auto n = static_cast<std::uint32_t>(m.vertices.size());
    for (std::uint32_t c = 0; c < crowd.size(); ++c) {
        crowd.animateCharacter(c, time, bones);
        const std::vector<skin::CpuSkinnedVertex> expected = skin::skinOnCpu(m, bones);
        const test::ReadbackVertices read = test::readSkinnedCharacter(context, renderer, c);
        for (std::uint32_t v = 0; v < n; ++v) {
            largest = std::max(largest, glm::length(glm::dvec3(read.positions[v]) - expected[v].position));
            EXPECT_EQ(read.normals[v].w, m.vertices[v].normal.w) << "material index lost at vertex " << v;
        }
    }
    return largest;
}

app::Rgba8Image renderImage(const gpu::VulkanContext& context, crowd::Crowd crowd, skin::Method method,
                               float time = 0.5f) {
    test::RendererOptions options;
    options.size = {64, 64};
    options.method = method;
    test::TestRenderer renderer(context, crowd, options);
    renderer.renderFrame(time);
    return renderer.readback();
}

void expectGpuMatchesCpu(const gpu::VulkanContext& context, const Asset& asset) {
    const model::SkinnedModel m = model::loadGltf(assetPath(asset));
    crowd::Crowd crowd(m, mixedCharacters(m, 4));
    // float32 on both sides of the same float matrices; allow 1e-5 of the crowd's extent (coordinates
    // reach a few character sizes from the origin).
    const double tolerance = 1e-5 * 4.0 * extent(m);
    for (skin::Method method : {skin::Method::TwoPass, skin::Method::TwoPassDirect, skin::Method::Compute})
        EXPECT_LE(gpuError(context, crowd, method), tolerance) << asset.file << " " << skin::methodName(method);
    // The vertex-shader methods leave no vertices to read back: they must draw the two-pass picture.
    const app::Rgba8Image twoPass = renderImage(context, crowd, skin::Method::TwoPass);
    const app::Rgba8Image vs = renderImage(context, crowd, skin::Method::VertexShader);
    EXPECT_GE(test::fractionOfMatchingPixels(vs, twoPass, 2), 0.995) << asset.file;
    EXPECT_LT(test::fractionOfMatchingPixels(twoPass, renderImage(context, crowd, skin::Method::TwoPass, 0.9f), 0), 1.0)
        << asset.file << ": the characters must be in the picture, and move";
}

}  // namespace

TEST_F(GpuTest, GltfFoxGpuSkinningMatchesCpuReference) {
    SKIP_WITHOUT(kFox);
    expectGpuMatchesCpu(*context, kFox);
}

TEST_F(GpuTest, GltfCesiumManGpuSkinningMatchesCpuReference) {
    SKIP_WITHOUT(kCesiumMan);
    expectGpuMatchesCpu(*context, kCesiumMan);
}

TEST_F(GpuTest, GltfRiggedSimpleGpuSkinningMatchesCpuReference) {
    SKIP_WITHOUT(kRiggedSimple);
    expectGpuMatchesCpu(*context, kRiggedSimple);
}

namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("crowd-gltf-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

struct Obj {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::uint32_t> faces;  // 1-based, as written
};

Obj readObj(const std::string& path) {
    Obj obj;
    std::ifstream file(path);
    std::string line;
    while (std::getline(file, line)) {
        std::istringstream in(line);
        std::string tag;
        in >> tag;
        glm::dvec3 v;
        if (tag == "v")
            in >> v.x >> v.y >> v.z, obj.positions.push_back(v);
        else if (tag == "vn")
            in >> v.x >> v.y >> v.z, obj.normals.push_back(v);
        else if (tag == "f") {
            for (int k = 0; k < 3; ++k) {
                std::string corner;
                in >> corner;
                obj.faces.push_back(static_cast<std::uint32_t>(std::stoul(corner.substr(0, corner.find('/')))));
            }
        }
    }
    return obj;
}

}  // namespace

TEST(GltfAssets, ListClipsPrintsTheModelAndItsClips) {
    SKIP_WITHOUT(kFox);
    const test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--model " + assetPath(kFox).string() + " --list-clips");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("Fox: 24 joints, 1728 vertices, 576 triangles"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0: Run (1.1250 s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1: Survey (3.4167 s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("2: Walk (0.7083 s)"), std::string::npos) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(GltfAssets, ExportPoseWritesTheSkinnedMeshAsTheSpecificationDefinesIt) {
    SKIP_WITHOUT(kCesiumMan);
    const std::string obj = tempPath("cesium.obj");
    const test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--model " + assetPath(kCesiumMan).string() + " --export-pose " + obj +
                                                  " --clip 0 --time 0.6");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Obj written = readObj(obj);
    std::filesystem::remove(obj);
    ASSERT_EQ(written.positions.size(), kCesiumMan.vertices);
    ASSERT_EQ(written.normals.size(), kCesiumMan.vertices);
    ASSERT_EQ(written.faces.size(), kCesiumMan.triangles * 3);
    EXPECT_EQ(*std::min_element(written.faces.begin(), written.faces.end()), 1u);
    EXPECT_EQ(*std::max_element(written.faces.begin(), written.faces.end()), kCesiumMan.vertices);
    const std::vector<glm::dvec3> expected =
        test::referenceSkinnedPositions(test::parseWithTinygltf(assetPath(kCesiumMan)), 0, 0.6);
    // crowd-render writes the vertices in its own order (levels of detail put the coarse levels' first):
    // compare each with the file's vertex it is.
    const std::vector<std::uint32_t> fileVertex = test::originalVertexOf(
        model::loadGltf(assetPath(kCesiumMan)), test::loadModel(assetPath(kCesiumMan).string(), 1));
    ASSERT_EQ(fileVertex.size(), expected.size());
    double largest = 0.0;
    for (std::size_t v = 0; v < expected.size(); ++v) {
        ASSERT_LT(fileVertex[v], expected.size());
        largest = std::max(largest, glm::length(written.positions[v] - expected[fileVertex[v]]));
    }
    EXPECT_LE(largest, 1e-5 * 2.0) << "CesiumMan is about 1.5 m tall";
    for (const glm::dvec3& n : written.normals) EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
}

TEST(GltfAssets, ExportPoseWorksForTheBuiltInModelsAndRejectsBadTimes) {
    const std::string obj = tempPath("soldier.obj");
    test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--model soldier --export-pose " + obj + " --clip run --time 0.3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const std::vector<skin::CpuSkinnedVertex> expected = skin::poseOnCpu(soldier, test::clipIndex(soldier, "run"), 0.3f);
    const Obj written = readObj(obj);
    std::filesystem::remove(obj);
    ASSERT_EQ(written.positions.size(), expected.size());
    for (std::size_t v = 0; v < expected.size(); ++v)
        EXPECT_LE(glm::length(written.positions[v] - expected[v].position), 1e-6) << v;

    r = test::runProgram(CROWD_RENDER_BINARY, "--export-pose " + obj + " --time soon");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "crowd-render: --time: 'soon' is not a number of seconds\n");
    r = test::runProgram(CROWD_RENDER_BINARY, "--time 1");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "crowd-render: --time needs --export-pose\n");
}

TEST(GltfAssets, CrowdRenderDrawsACrowdOfEachAssetWithValidationSilent) {
    int present = 0;
    for (const Asset& asset : kAssets) {
        if (!haveAsset(asset)) continue;
        ++present;
        const std::string png = tempPath("crowd.png");
        const test::ProgramResult r =
            test::runProgram(CROWD_RENDER_BINARY, "--model " + assetPath(asset).string() +
                                                      " --count 4 --frames 2 --size 64x64 --validation --out " + png);
        EXPECT_EQ(r.exitCode, 0) << asset.file << "\n" << r.err;
        EXPECT_GT(std::filesystem::file_size(png), 100u);
        std::filesystem::remove(png);
    }
    if (present == 0) GTEST_SKIP() << "no shared assets in " << CROWD_SHARED_ASSETS_DIR;
}

TEST_F(GpuTest, TwoTexturedGltfModelsInOneCrowdRenderAsTheirOwnCrowdsDo) {
    SKIP_WITHOUT(kFox);
    SKIP_WITHOUT(kCesiumMan);
    // Both textured: in the mixed crowd the Fox's texture is in slot 2, alone in slot 1, so a crowd
    // that mixed up slots or material bases would not match.
    const model::SkinnedModel man = test::loadModel(assetPath(kCesiumMan).string(), 1);
    const model::SkinnedModel fox = test::loadModel(assetPath(kFox).string(), 1);
    ASSERT_FALSE(man.baseColorTexture.rgba.empty());
    ASSERT_FALSE(fox.baseColorTexture.rgba.empty());
    const test::MixedCrowdMatch match = test::compareMixedCrowd(*device, man, fox, 1.0f, "cesiumman-fox");
    EXPECT_GT(match.firstModelPixels, 100u);
    EXPECT_GT(match.secondModelPixels, 30u);
    // Same characters, same math: only an edge pixel may round differently.
    EXPECT_GE(match.matchingFraction, 0.995) << "images left in " << test::artifactPath("");
    EXPECT_GE(match.firstModelMatching, 0.97);
    EXPECT_GE(match.secondModelMatching, 0.97);
}
