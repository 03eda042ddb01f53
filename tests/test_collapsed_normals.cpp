// Normals of collapsed parts: a zero scale key (a common way to hide a part) or zero inverse bind
// matrices map a vertex's normal to nothing, and normalizing that gave NaN on the CPU (--export-pose)
// and on the GPU (every skinning method). Such a vertex now keeps its bind-pose normal, on both.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "skin/cpu_skinning.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"
#include "support/run_program.h"

namespace {

// The strip character with a clip "hide" that scales its tip joint to 0 for a whole second: the top
// row collapses onto the tip, the middle row (half tip, half root) keeps a finite normal.
test::GltfBuilder stripWithHiddenTip() {
    test::GltfBuilder b = test::stripCharacter();
    const int times = b.floats({0.0f, 1.0f}, "SCALAR");
    const int scales = b.floats({0, 0, 0, 0, 0, 0}, "VEC3");
    b.doc["animations"].push_back(
        {{"name", "hide"},
         {"samplers", {{{"input", times}, {"output", scales}, {"interpolation", "LINEAR"}}}},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "scale"}}}}}}});
    return b;
}

// The strip character whose inverse bind matrices are all zero: every vertex collapses to the origin.
test::GltfBuilder stripWithZeroInverseBinds() {
    test::GltfBuilder b = test::stripCharacter();
    b.doc["skins"][0]["inverseBindMatrices"] = b.floats(std::vector<float>(32, 0.0f), "MAT4");
    return b;
}

std::filesystem::path writeTemp(const test::GltfBuilder& b, const std::string& name) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("crowd-collapsed-" + std::to_string(::getpid()) + "-" + name);
    std::ofstream(path) << b.gltf();
    return path;
}

// The `vn` lines of an OBJ file, read with strtod so that "nan" and "inf" read as what they are.
std::vector<glm::dvec3> objNormals(const std::filesystem::path& path) {
    std::vector<glm::dvec3> normals;
    std::ifstream file(path);
    for (std::string line; std::getline(file, line);) {
        if (line.rfind("vn ", 0) != 0) continue;
        const char* at = line.c_str() + 3;
        char* end = nullptr;
        glm::dvec3 n;
        for (int k = 0; k < 3; ++k) n[k] = std::strtod(at, &end), at = end;
        normals.push_back(n);
    }
    return normals;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

class CollapsedNormalsOnGpu : public test::GpuTest {};

}  // namespace

TEST(CollapsedNormals, CpuSkinningWithZeroBonesKeepsTheBindNormals) {
    const model::SkinnedModel strip = test::loadText(test::stripCharacter().gltf());
    const std::vector<gpu::BoneRows> zero(strip.skeleton.jointCount(), gpu::BoneRows{});
    const std::vector<skin::CpuSkinnedVertex> skinned = skin::skinOnCpu(strip, zero);
    ASSERT_EQ(skinned.size(), strip.vertices.size());
    for (std::size_t v = 0; v < skinned.size(); ++v) {
        EXPECT_EQ(skinned[v].position, glm::dvec3(0.0));
        EXPECT_EQ(skinned[v].normal, glm::dvec3(glm::vec3(strip.vertices[v].normal))) << "vertex " << v;
    }
}

TEST(CollapsedNormals, ExportPoseWritesFiniteUnitNormals) {
    for (const auto& [name, builder, clip] :
         {std::tuple{"zero-scale.gltf", stripWithHiddenTip(), "hide"},
          std::tuple{"zero-inverse-bind.gltf", stripWithZeroInverseBinds(), "bend"}}) {
        const std::filesystem::path gltf = writeTemp(builder, name);
        const std::filesystem::path obj = gltf.string() + ".obj";
        const test::ProgramResult r = test::runProgram(
            CROWD_RENDER_BINARY, "--model " + gltf.string() + " --export-pose " + obj.string() + " --clip " + clip +
                                     " --time 0.5");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        const std::vector<glm::dvec3> normals = objNormals(obj);
        EXPECT_EQ(normals.size(), 6u) << name;
        for (const glm::dvec3& n : normals) {
            EXPECT_TRUE(finite(n)) << name;
            EXPECT_NEAR(glm::length(n), 1.0, 1e-6) << name;
        }
        std::filesystem::remove(gltf);
        std::filesystem::remove(obj);
    }
}

TEST_F(CollapsedNormalsOnGpu, EverySkinningMethodWritesFiniteNormals) {
    for (const auto& [name, builder, clip] :
         {std::tuple{"zero-scale.gltf", stripWithHiddenTip(), 1u}, std::tuple{"zero-inverse-bind.gltf", stripWithZeroInverseBinds(), 0u}}) {
        const std::filesystem::path gltf = writeTemp(builder, name);
        const model::SkinnedModel strip = test::loadModel(gltf.string(), 1);
        std::filesystem::remove(gltf);
        ASSERT_EQ(strip.clips[clip].name, clip == 1u ? "hide" : "bend");
        std::vector<crowd::Character> characters(2);
        characters[0].clip = characters[1].clip = clip;
        characters[1].position = glm::vec3(3.0f, 0.0f, 0.0f);
        crowd::Crowd crowd(strip, characters);
        for (skin::Method method : {skin::Method::Compute, skin::Method::TwoPass, skin::Method::TwoPassDirect}) {
            test::RendererOptions options;
            options.size = {32, 32};
            options.method = method;
            options.cull.mode = render::CullMode::Off;
            options.cull.lod = false;
            test::TestRenderer renderer(*device, crowd, options);
            const float time = 0.5f;
            renderer.renderFrame(time);
            renderer.finish();
            std::vector<gpu::BoneRows> bones(strip.skeleton.jointCount());
            for (std::uint32_t c = 0; c < crowd.size(); ++c) {
                crowd.animateCharacter(c, time, bones);
                const std::vector<skin::CpuSkinnedVertex> expected = skin::skinOnCpu(strip, bones);
                const test::ReadbackVertices gpu = test::readSkinnedCharacter(*context, renderer, c);
                ASSERT_EQ(gpu.normals.size(), expected.size());
                for (std::size_t v = 0; v < expected.size(); ++v) {
                    const glm::dvec3 normal(gpu.normals[v]);
                    ASSERT_TRUE(finite(normal)) << name << " " << skin::methodName(method) << " vertex " << v;
                    EXPECT_LE(glm::length(normal - expected[v].normal), 1e-5)
                        << name << " " << skin::methodName(method) << " vertex " << v;
                }
            }
        }
    }
}
