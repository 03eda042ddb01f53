// Pass 1 (fragment-shader skinning) and the other skinning passes read back from the GPU equal the
// CPU reference; characters are independent; every method draws the same picture.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "model/procedural_models.h"
#include "app/crowd_renderer.h"
#include "crowd/cull_reference.h"
#include "skin/cpu_skinning.h"
#include "skin/fragment_skinning.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

// A few characters, each with its own clip, phase and speed, as the paper animates them.
std::vector<crowd::Character> mixedCharacters(const model::SkinnedModel& model, std::uint32_t count) {
    std::vector<crowd::Character> characters(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        crowd::Character& c = characters[i];
        c.clip = i % static_cast<std::uint32_t>(model.clips.size());
        c.timeOffset = 0.137f * static_cast<float>(i);
        c.speed = 0.8f + 0.1f * static_cast<float>(i % 5);
        c.position = glm::vec3(3.0f * static_cast<float>(i % 4), 0.0f, 3.0f * static_cast<float>(i / 4));
        c.heading = 0.4f * static_cast<float>(i);
    }
    return characters;
}

// Every character drawn at LOD 0: no culling, no LOD.
render::CullSettings fullDetail() {
    render::CullSettings cull;
    cull.mode = render::CullMode::Off;
    cull.lod = false;
    return cull;
}

// Largest distance between GPU pass-1 output and the CPU reference, over every vertex of every character.
struct SkinError {
    double position = 0.0;
    double normal = 0.0;
};

// A 64x64 frame skinned by `method` under culling settings `cull`.
test::RendererOptions skinningOptions(skin::Method method, const render::CullSettings& cull) {
    test::RendererOptions options;
    options.size = {64, 64};
    options.method = method;
    options.cull = cull;
    return options;
}

SkinError compareWithCpu(const gpu::VulkanContext& context, const model::SkinnedModel& model,
                         crowd::Crowd crowd, std::uint32_t maxTargetDimension, skin::Method method,
                         const render::CullSettings& cull = fullDetail()) {
    test::RendererOptions options = skinningOptions(method, cull);
    options.maxTargetDimension = maxTargetDimension;
    test::TestRenderer renderer(context, crowd, options);
    const float time = 0.75f;
    renderer.renderFrame(time);
    renderer.finish();

    SkinError error;
    std::vector<gpu::BoneRows> bones(model.skeleton.jointCount());
    const std::map<std::uint32_t, test::DrawnCharacter> drawn = test::readDrawList(context, renderer);
    EXPECT_EQ(drawn.size(), crowd.size()) << "every character is in view";
    const std::uint32_t expectedLod = !cull.lod ? 0u : cull.lodThresholds[1] > 1e4f ? 2u : cull.lodThresholds[0] > 1e4f ? 1u : 99u;
    for (const auto& [c, where] : drawn) {
        if (expectedLod != 99u) {
            EXPECT_EQ(where.lod, expectedLod) << "character " << c;
        }
        EXPECT_EQ(where.vertexCount, render::lodsOf(model)[where.lod].vertexCount);
        crowd.animateCharacter(c, time, bones);
        const std::vector<skin::CpuSkinnedVertex> expected = skin::skinOnCpu(model, bones);
        const test::ReadbackVertices gpu = test::readSkinnedVertices(context, renderer.method().skinnedVertices(),
                                                                     where.firstVertex, where.vertexCount);
        for (std::uint32_t v = 0; v < where.vertexCount; ++v) {
            error.position = std::max(error.position, glm::length(glm::dvec3(gpu.positions[v]) - expected[v].position));
            error.normal = std::max(error.normal, glm::length(glm::dvec3(gpu.normals[v]) - expected[v].normal));
            EXPECT_EQ(gpu.normals[v].w, model.vertices[v].normal.w) << "material index lost at vertex " << v;
        }
    }
    return error;
}

void expectPassOneMatchesCpu(const gpu::VulkanContext& context, const model::SkinnedModel& model,
                             std::uint32_t maxTargetDimension, skin::Method method = skin::Method::TwoPass) {
    crowd::Crowd crowd(model, mixedCharacters(model, 6));
    const SkinError error = compareWithCpu(context, model, crowd, maxTargetDimension, method);
    // float32 skinning of coordinates up to ~10 m: a few ulps of 10 m is ~1e-6 m; allow 1e-5 of the height.
    EXPECT_LE(error.position, 1e-5 * model.height()) << model.name << " " << skin::methodName(method);
    EXPECT_LE(error.normal, 1e-5) << model.name << " " << skin::methodName(method);
}

}  // namespace

TEST_F(GpuTest, TwoPassMatchesCpuReferenceSoldier) {
    expectPassOneMatchesCpu(*context, model::makeSoldier(1), 0);
}

TEST_F(GpuTest, TwoPassMatchesCpuReferenceHorse) {
    expectPassOneMatchesCpu(*context, model::makeHorse(1), 0);
}

TEST_F(GpuTest, TwoPassTiledTargetsMatchCpuReference) {
    // A 256-texel limit wraps each character over several rows and splits the crowd into tiles,
    // as a large crowd does against the real 16k-32k limits.
    const model::SkinnedModel soldier = model::makeSoldier(1);
    const std::uint32_t limit = 256;
    // 6 characters of 810 vertices wrap over rows of 256 texels, and 19 rows over... one tile; 64
    // texels make several tiles (each 64 x 64), with characters split across tiles.
    ASSERT_GT(soldier.vertices.size(), limit);
    expectPassOneMatchesCpu(*context, soldier, limit);
    ASSERT_GT(skin::planSkinTargets(6 * soldier.vertices.size(), 64).tileCount, 1u);
    expectPassOneMatchesCpu(*context, soldier, 64);
}

TEST_F(GpuTest, DirectFragmentAndComputeSkinningMatchCpuReference) {
    for (const char* name : {"soldier", "horse"}) {
        const model::SkinnedModel model = test::loadModel(name, 1);
        expectPassOneMatchesCpu(*context, model, 0, skin::Method::TwoPassDirect);
        expectPassOneMatchesCpu(*context, model, 256, skin::Method::TwoPassDirect);  // tiled
        expectPassOneMatchesCpu(*context, model, 0, skin::Method::Compute);
        expectPassOneMatchesCpu(*context, model, 0, skin::Method::Static);  // skins its first frame
    }
}

TEST_F(GpuTest, EveryLevelOfDetailSkinsLikeTheCpuReference) {
    // Thresholds no character reaches (LOD 2) or that every character passes but the first (LOD 1).
    render::CullSettings lod1, lod2;
    lod1.mode = lod2.mode = render::CullMode::Off;
    lod1.lodThresholds[0] = 1e6f, lod1.lodThresholds[1] = 1e-3f;
    lod2.lodThresholds[0] = 1e6f, lod2.lodThresholds[1] = 1e5f;
    for (const char* name : {"soldier", "horse"}) {
        const model::SkinnedModel model = test::loadModel(name, 1);
        crowd::Crowd crowd(model, mixedCharacters(model, 6));
        for (skin::Method method : {skin::Method::Compute, skin::Method::TwoPass, skin::Method::TwoPassDirect}) {
            for (const render::CullSettings& cull : {lod1, lod2}) {
                const SkinError error = compareWithCpu(*context, model, crowd, 0, method, cull);
                EXPECT_LE(error.position, 1e-5 * model.height()) << name << " " << skin::methodName(method);
                EXPECT_LE(error.normal, 1e-5) << name << " " << skin::methodName(method);
            }
        }
    }
}

namespace {

// The pose-sphere diameters in pixels the renderer's culling saw in its last frame, smallest first.
std::vector<float> projectedSizes(const test::TestRenderer& renderer) {
    const gpu::CullUniforms uniforms = renderer.cullUniforms();
    std::vector<float> sizes;
    for (const gpu::CharacterRecord& record : renderer.buffers().records())
        sizes.push_back(crowd::projectedDiameter(crowd::worldSphere(record, renderer.pool().models()[record.ids.x]),
                                                 uniforms.camera));
    std::sort(sizes.begin(), sizes.end());
    return sizes;
}

// How far the GPU's skinned vertices of fading characters are from the CPU's morph of its own skinning
// at the share culling gave each, and how far the morph moved the vertices at most.
struct MorphError {
    double position = 0.0, normal = 0.0, moved = 0.0;
    std::uint32_t fading = 0;  // characters with a share strictly between 0 and 1
};

MorphError compareMorphWithCpu(const gpu::VulkanContext& context, const model::SkinnedModel& model,
                               crowd::Crowd crowd, skin::Method method, const render::CullSettings& cull,
                               float time) {
    test::RendererOptions options = skinningOptions(method, cull);
    options.shadows = false;
    test::TestRenderer renderer(context, crowd, options);
    renderer.renderFrame(time);
    renderer.finish();
    const std::vector<std::uint32_t> states = test::readShadowLists(context, renderer).states;
    const std::vector<model::LodMorphTarget> targets = model::lodMorphTargets(model, render::lodsOf(model));
    std::vector<gpu::BoneRows> bones(model.skeleton.jointCount());
    MorphError error;
    for (const auto& [c, where] : test::readDrawList(context, renderer)) {
        const std::uint32_t steps = states[c] >> FADE_SHIFT;
        if (where.lod + 1 >= LOD_COUNT) continue;
        if (steps > 0 && steps < FADE_STEPS) ++error.fading;
        crowd.animateCharacter(c, time, bones);
        const std::vector<skin::CpuSkinnedVertex> own = skin::skinOnCpu(model, bones);
        const std::vector<skin::CpuSkinnedVertex> expected = test::cpuFadedCharacter(model, targets, own, where.lod, states[c]);
        const test::ReadbackVertices gpu =
            test::readSkinnedVertices(context, renderer.method().skinnedVertices(), where.firstVertex, where.vertexCount);
        for (std::uint32_t v = 0; v < where.vertexCount; ++v) {
            error.position = std::max(error.position, glm::length(glm::dvec3(gpu.positions[v]) - expected[v].position));
            error.normal = std::max(error.normal, glm::length(glm::dvec3(gpu.normals[v]) - expected[v].normal));
            error.moved = std::max(error.moved, glm::length(expected[v].position - own[v].position));
        }
    }
    return error;
}

}  // namespace

// Fades between mesh levels are geomorphs made while skinning (shaders/lod_morph.glsl.inc): a
// character in the band of a level threshold is skinned at the finer level with the vertices the
// coarser one drops moved by its share toward their targets. Every method that skins into a buffer
// writes what the CPU reference computes (its own skinning, then model::LodMorphTarget's blend), for
// characters spread over the band of LOD 0 -> 1 and of LOD 1 -> 2.
TEST_F(GpuTest, CharactersFadingBetweenLevelsMorphLikeTheCpuReference) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Crowd crowd(soldier, mixedCharacters(soldier, 8));
    render::CullSettings cull;
    cull.mode = render::CullMode::Off;  // every character drawn
    cull.hysteresis = 0.5f;             // bands between mesh levels of T to 2 T
    test::TestRenderer probe(*context, crowd, skinningOptions(skin::Method::Compute, cull));
    probe.renderFrame(0.75f);
    probe.finish();
    const std::vector<float> sizes = projectedSizes(probe);
    // A threshold whose band's middle (1.5 T) is the middle of the sizes, wide enough to hold them all.
    const float middle = 0.5f * (sizes.front() + sizes.back()), threshold = middle / 1.5f;
    ASSERT_LT(sizes.back(), 1.9f * threshold);
    ASSERT_GT(sizes.front(), 1.1f * threshold);
    render::CullSettings lod0 = cull, lod1 = cull;
    lod0.lodThresholds[0] = threshold, lod0.lodThresholds[1] = 1e-3f;  // LOD 0 fading into 1
    lod1.lodThresholds[0] = 1e6f, lod1.lodThresholds[1] = threshold;   // LOD 1 fading into 2
    const std::pair<const char*, render::CullSettings> bands[] = {{"LOD 0 -> 1", lod0}, {"LOD 1 -> 2", lod1}};
    for (skin::Method method : {skin::Method::Compute, skin::Method::TwoPass, skin::Method::TwoPassDirect}) {
        for (const auto& [band, settings] : bands) {
            const MorphError error = compareMorphWithCpu(*context, soldier, crowd, method, settings, 0.75f);
            std::printf("%s, %s: %u characters fading, vertices moved up to %.4f m, GPU against CPU %.2e m, normals %.2e\n",
                        skin::methodName(method), band, error.fading, error.moved, error.position, error.normal);
            EXPECT_GE(error.fading, 4u) << band;
            EXPECT_GT(error.moved, 1e-3 * soldier.height()) << band << ": the morph moved nothing";
            EXPECT_LE(error.position, 1e-5 * soldier.height()) << skin::methodName(method) << " " << band;
            EXPECT_LE(error.normal, 1e-4) << skin::methodName(method) << " " << band;
        }
    }
}

TEST_F(GpuTest, TiledTargetsRespectTheLimit) {
    const model::SkinnedModel soldier = model::makeSoldier(1);
    crowd::Crowd crowd(soldier, mixedCharacters(soldier, 40));
    test::RendererOptions options;
    options.size = {32, 32};
    options.maxTargetDimension = 64;
    test::TestRenderer renderer(*device, crowd, options);
    const auto& layout = static_cast<skin::FragmentSkinning&>(renderer.method()).layout();
    EXPECT_GT(layout.tileCount, 1u);
    for (std::uint32_t t = 0; t < layout.tileCount; ++t) {
        EXPECT_LE(layout.tileExtent(t).width, 64u);
        EXPECT_LE(layout.tileExtent(t).height, 64u);
    }
}

TEST_F(GpuTest, CharactersWithEqualPhasesHaveEqualPosesAndDifferentPhasesDiffer) {
    const model::SkinnedModel soldier = model::makeSoldier(1);
    const std::uint32_t walk = static_cast<std::uint32_t>(soldier.findClip("walk"));
    std::vector<crowd::Character> characters(3);
    characters[0] = {walk, 0.2f, 1.0f, glm::vec3(0, 0, 0), 0.0f};
    characters[1] = {walk, 0.2f, 1.0f, glm::vec3(4, 0, 0), 0.0f};  // same phase, elsewhere
    characters[2] = {walk, 0.6f, 1.0f, glm::vec3(8, 0, 0), 0.0f};  // other phase
    for (crowd::Character& c : characters) c.props = 0x1u;  // the same props (the default choice hashes the index)
    crowd::Crowd crowd(soldier, characters);
    test::RendererOptions options;
    options.size = {32, 32};
    options.cull = fullDetail();
    test::TestRenderer renderer(*device, crowd, options);
    renderer.renderFrame(0.3f);
    renderer.finish();
    const auto n = static_cast<std::uint32_t>(soldier.vertices.size());
    std::vector<test::ReadbackVertices> read;
    for (std::uint32_t c = 0; c < 3; ++c) read.push_back(test::readSkinnedCharacter(*context, renderer, c));
    double equalPhase = 0.0, otherPhase = 0.0;
    for (std::uint32_t v = 0; v < n; ++v) {
        // Compare poses in each character's own frame: subtract its placement.
        const glm::vec3 a = glm::vec3(read[0].positions[v]) - characters[0].position;
        const glm::vec3 b = glm::vec3(read[1].positions[v]) - characters[1].position;
        const glm::vec3 c = glm::vec3(read[2].positions[v]) - characters[2].position;
        equalPhase = std::max<double>(equalPhase, glm::length(a - b));
        otherPhase = std::max<double>(otherPhase, glm::length(a - c));
    }
    EXPECT_LE(equalPhase, 1e-5 * soldier.height());
    EXPECT_GE(otherPhase, 0.05 * soldier.height()) << "a different phase must move the limbs visibly";
}

namespace {

app::Rgba8Image renderScene(const gpu::VulkanContext& context, crowd::Crowd crowd, skin::Method method,
                               std::uint32_t frames, bool fades = true) {
    test::RendererOptions options;
    options.size = {192, 128};
    options.method = method;
    options.cull.lodFade = fades;
    test::TestRenderer renderer(context, crowd, options);
    for (std::uint32_t f = 0; f < frames; ++f) renderer.renderFrame(app::frameTime(f));
    return renderer.readback();
}

void expectMethodsDrawTheSamePicture(const gpu::VulkanContext& context, const std::string& modelName) {
    const model::SkinnedModel model = test::loadModel(modelName, 1);
    app::SceneOptions scene;
    scene.model = modelName;
    scene.count = 16;
    scene.clip = "random";
    crowd::Crowd crowd(model, test::buildCharacters(model, scene));
    // One frame: "static" skins only its first frame, so every method shows the same poses there.
    // Level changes fade only in the methods that skin into a buffer every frame (docs/picture-quality.md,
    // "No pops"); the vertex-shader methods and the static ceiling switch at once, so they are compared
    // with fades off.
    const app::Rgba8Image twoPass = renderScene(context, crowd, skin::Method::TwoPass, 1);
    const app::Rgba8Image twoPassNoFades = renderScene(context, crowd, skin::Method::TwoPass, 1, false);
    for (skin::Method method : skin::allMethods()) {
        if (method == skin::Method::TwoPass) continue;
        const bool fades = method != skin::Method::VertexShader && method != skin::Method::VertexShaderInstanced &&
                           method != skin::Method::Static;
        const app::Rgba8Image other = renderScene(context, crowd, method, 1, fades);
        const app::Rgba8Image& reference = fades ? twoPass : twoPassNoFades;
        const double matching = test::fractionOfMatchingPixels(other, reference, 2);
        if (matching < 0.995) {
            app::writePng(test::artifactPath(modelName + "-" + skin::methodName(method) + ".png"), other);
            app::writePng(test::artifactPath(modelName + "-two-pass.png"), reference);
        }
        // Same math in every method; only rounding (fused multiply-adds, stage differences) may move
        // an edge pixel, so at least 99.5% of pixels agree within 2/255 per channel.
        EXPECT_GE(matching, 0.995) << modelName << " " << skin::methodName(method) << ": images left in "
                                   << test::artifactPath("");
    }
    // And the match is not trivial: the animated crowd visibly changes the picture a few frames later.
    const app::Rgba8Image later = renderScene(context, crowd, skin::Method::TwoPass, 12);
    EXPECT_LT(test::fractionOfMatchingPixels(twoPass, later, 2), 0.99) << "the crowd must be visible and moving";
}

}  // namespace

// A pool without textured materials draws with the fragment shader that reads no texture coordinates
// (draw.frag.glsl, kTextured 0); a pool with one, with the shader that samples. The soldier given a
// one-texel texture on every material: white must draw what the untextured soldier draws (the sample
// is the identity there), and dark grey must darken the characters, so a renderer that kept the
// untextured variant for a textured pool fails.
TEST_F(GpuTest, ATexturedPoolSamplesItsTextureAndWhiteChangesNothing) {
    const model::SkinnedModel plain = test::loadModel("soldier", 1);
    auto textured = [&](std::uint8_t level) {
        model::SkinnedModel m = plain;
        m.uvs.assign(m.vertices.size(), glm::vec2(0.5f));
        m.baseColorTexture = {1, 1, {level, level, level, 255}};
        m.texturedMaterials = (1u << m.materialColors.size()) - 1u;
        return m;
    };
    app::SceneOptions scene;
    scene.count = 16;
    auto picture = [&](const model::SkinnedModel& m) {
        return renderScene(*context, crowd::Crowd(m, test::buildCharacters(m, scene)), skin::Method::Compute, 1);
    };
    auto meanLevel = [](const app::Rgba8Image& image) {
        double sum = 0.0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) sum += i % 4 == 3 ? 0.0 : image.pixels[i];
        return sum / (0.75 * static_cast<double>(image.pixels.size()));
    };
    const app::Rgba8Image untextured = picture(plain), white = picture(textured(255)), dark = picture(textured(64));
    EXPECT_GE(test::fractionOfMatchingPixels(white, untextured, 1), 0.999);
    const double darkened = 1.0 - test::fractionOfMatchingPixels(dark, untextured, 8);
    std::printf("untextured mean level %.2f, white texture %.2f, dark grey %.2f (%.1f %% of pixels darker by over 8)\n",
                meanLevel(untextured), meanLevel(white), meanLevel(dark), 100.0 * darkened);
    EXPECT_GT(darkened, 0.02) << "the texture must show on the characters";
    EXPECT_LT(meanLevel(dark), meanLevel(untextured) - 1.0);
}

TEST_F(GpuTest, AllMethodsDrawTheSameSoldiers) { expectMethodsDrawTheSamePicture(*context, "soldier"); }

TEST_F(GpuTest, AllMethodsDrawTheSameHorses) { expectMethodsDrawTheSamePicture(*context, "horse"); }

// The mounted model (docs/cavalry.md) is one character to every method: horse and rider, walking and
// galloping at their phases, skinned on the GPU equal the CPU reference, at every level of detail.
TEST_F(GpuTest, MountedModelSkinsLikeTheCpuReference) {
    const model::SkinnedModel cavalry = test::loadModel("cavalry", 1);
    for (skin::Method method : {skin::Method::TwoPass, skin::Method::TwoPassDirect, skin::Method::Compute,
                                skin::Method::Static})
        expectPassOneMatchesCpu(*context, cavalry, 0, method);
    render::CullSettings lod2;
    lod2.mode = render::CullMode::Off;
    lod2.lodThresholds[0] = 1e6f, lod2.lodThresholds[1] = 1e5f;
    crowd::Crowd crowd(cavalry, mixedCharacters(cavalry, 6));
    const SkinError error = compareWithCpu(*context, cavalry, crowd, 0, skin::Method::Compute, lod2);
    EXPECT_LE(error.position, 1e-5 * cavalry.height());
    EXPECT_LE(error.normal, 1e-5);
}

TEST_F(GpuTest, AllMethodsDrawTheSameCavalry) { expectMethodsDrawTheSamePicture(*context, "cavalry"); }
