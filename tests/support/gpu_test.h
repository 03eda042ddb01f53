#pragma once
// Test support for GPU tests: a Vulkan context with the Khronos validation layer and
// synchronization validation; any validation message during a test fails it.
#include <cstring>
#include <map>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "crowd/cull_reference.h"
#include "app/crowd_renderer.h"
#include "app/host_device.h"
#include "app/options.h"
#include "app/png_writer.h"
#include "crowd/crowd.h"
#include "frame/crowd_recorder.h"
#include "gpu/vulkan_context.h"
#include "model/lod_morph.h"
#include "skin/cpu_skinning.h"
#include "skin/skinning_method.h"

namespace test {

// The programs' device (app::HostDevice, validated) and the library's view of it with a queue of its
// own, so each pass can be checked alone with its setup submitted at once.
class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::unique_ptr<app::HostDevice> device;
    std::unique_ptr<gpu::VulkanContext> context;
};

// The programs' frame driver's options with the library's internal ones (a shared atlas, a smaller
// target limit, an internal method), as the tests need them.
struct RendererOptions : frame::RecorderOptions {
    RendererOptions() { sky = true; }  // the programs' frame (app::rendererSettings): no colour clear
    VkExtent2D size{1280, 720};
    app::PassClock passClock = app::PassClock::TimestampQueries;
};

// The programs' device behind a GpuTest's library context.
const app::HostDevice& hostOf(const gpu::VulkanContext& context);

// A public crowd over an internal crowd the test keeps (borrowed, not moved).
crowdgpu::Crowd borrowCrowd(crowd::Crowd& crowd);

struct BorrowedCrowd {
    explicit BorrowedCrowd(crowd::Crowd& crowd) : publicCrowd(borrowCrowd(crowd)) {}
    crowdgpu::Crowd publicCrowd;
};

// TestRenderer, the programs' frame driver, over an internal crowd and internal options, with
// the library's internals at hand for checks (its recorder, lists, buffers, method).
class TestRenderer : private BorrowedCrowd, public app::CrowdRenderer {
public:
    TestRenderer(const app::HostDevice& device, crowd::Crowd& crowd, const RendererOptions& options);
    // On the device of the test's context (the GpuTest's own), for helpers that take only the context.
    TestRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd, const RendererOptions& options);
    frame::CrowdRecorder& recorder() const;
    skin::SkinningMethod& method() { return recorder().method(); }
    const render::GeometryPool& pool() const { return recorder().pool(); }
    const render::CrowdBuffers& buffers() const { return recorder().buffers(); }
    const render::DrawLists& drawLists() const { return recorder().drawLists(); }
    const render::CullPass& cullPass() const { return recorder().cullPass(); }
    std::shared_ptr<const render::ImpostorAtlas> impostorAtlas() const { return recorder().impostorAtlas(); }
    const render::CrowdShape& shape() const { return recorder().shape(); }
    const render::CullSettings& cull() const { return recorder().cull(); }
    void setCull(const render::CullSettings& cull);
    // What the cull pass gets for the current camera and settings (the CPU reference takes the same).
    gpu::CullUniforms cullUniforms() const;
};

// The mixed scene's crowd: `count` soldiers and horses, 3:1, on a grid.
crowd::Crowd mixedCrowd(const model::SkinnedModel& soldier, const model::SkinnedModel& horse, std::uint32_t count);
// The programs' crowd layout (app::buildCrowd) as internal characters of one model.
std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const app::SceneOptions& scene);
// Where an internal crowd stands, for the programs' camera paths.
app::CrowdShape shapeOf(const crowd::Crowd& crowd);
// The programs' camera of the library's internal one.
app::Camera appCamera(const render::Camera& camera);
inline app::Camera appCamera(const app::Camera& camera) { return camera; }
render::Camera internalCamera(const app::Camera& camera);
// Counts of the public kind from a renderer's stats, as the internal kind.
render::LodCounts internalCounts(const crowdgpu::FrameCounts& counts);

// The clip of this name (or index text), else the model's default clip, as app::clipIndex picks it.
std::uint32_t clipIndex(const model::SkinnedModel& model, const std::string& clip);

// The public method of an internal one.
crowdgpu::Method publicMethod(skin::Method method);
// A model as the programs load it (app::loadModel), as the library holds it.
model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed = 1);
// The built-in soldier and horse of seed 1, loaded once per process, for tests that only read them.
const model::SkinnedModel& soldier();
const model::SkinnedModel& horse();

// The world-space positions and normals (xyz, w as written) of one character, read back from the GPU.
struct ReadbackVertices {
    std::vector<glm::vec4> positions;
    std::vector<glm::vec4> normals;
};
ReadbackVertices readSkinnedVertices(const gpu::VulkanContext& context, const render::SkinnedVertices& vertices,
                                     std::uint32_t firstVertex, std::uint32_t vertexCount);

// Characters in one sorted list and not the other (GPU lists against the CPU reference's).
std::vector<std::uint32_t> differ(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b);

// A device buffer's bytes, copied to the host.
std::vector<std::byte> readBuffer(const gpu::VulkanContext& context, const gpu::Buffer& buffer);
// The same as whole elements of T.
template <typename T>
std::vector<T> readAll(const gpu::VulkanContext& context, const gpu::Buffer& buffer) {
    const std::vector<std::byte> bytes = readBuffer(context, buffer);
    std::vector<T> out(bytes.size() / sizeof(T));
    std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

// The last frame's visible lists, per bucket, sorted (the GPU's atomics append in any order).
crowd::VisibleLists readVisibleLists(const gpu::VulkanContext& context, const TestRenderer& renderer);
// The last frame's impostor list (impostor-level and demoted characters in view), sorted.
std::vector<std::uint32_t> readImpostorList(const gpu::VulkanContext& context, const TestRenderer& renderer);
// The last frame's shadow lists (mesh casters per bucket of their shadow level, casting impostors), sorted,
// and every character's shadow state (gpu_types.h, SHADOW_*).
crowd::ShadowLists readShadowLists(const gpu::VulkanContext& context, const TestRenderer& renderer);
// The character records the GPU culled from in the last frame (the motion pass writes them).
std::vector<gpu::CharacterRecord> readCharacterRecords(const gpu::VulkanContext& context,
                                                       const TestRenderer& renderer);

// One character in the last frame's draw list: its level of detail and its skinned vertices.
struct DrawnCharacter {
    std::uint32_t lod = 0;
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
};
// The last frame's compacted draw list, by character (culled characters are absent); call after finish().
std::map<std::uint32_t, DrawnCharacter> readDrawList(const gpu::VulkanContext& context,
                                                     const TestRenderer& renderer);

// The CPU reference of a drawn character's skinned vertices at level `lod`: `own` (skin::skinOnCpu with
// its bones), and, when its state word (gpu_types.h, FADE_SHIFT) says it fades into the next coarser
// mesh level, the vertices that level drops moved by the share (skin::morphOnCpu toward `targets`,
// model::lodMorphTargets of the model's render::lodsOf).
std::vector<skin::CpuSkinnedVertex> cpuFadedCharacter(const model::SkinnedModel& model,
                                                      const std::vector<model::LodMorphTarget>& targets,
                                                      const std::vector<skin::CpuSkinnedVertex>& own, std::uint32_t lod,
                                                      std::uint32_t state);

// The last frame's skinned vertices of one drawn character (it must be in the draw list).
ReadbackVertices readSkinnedCharacter(const gpu::VulkanContext& context, TestRenderer& renderer,
                                      std::uint32_t character);

// Fraction of pixels whose every channel differs by at most `tolerance` (out of 255).
double fractionOfMatchingPixels(const app::Rgba8Image& a, const app::Rgba8Image& b, int tolerance);
// The pixels a shadow darkened: darker in `shadowed` than in `unshadowed` by more than `levels` of 255
// in every colour channel.
std::vector<bool> darkenedPixels(const app::Rgba8Image& shadowed, const app::Rgba8Image& unshadowed, int levels);
// Whether pixel `pixel` (row-major) of the two images differs by at most `tolerance` in R, G and B.
bool pixelWithin(const app::Rgba8Image& a, const app::Rgba8Image& b, std::size_t pixel, int tolerance);
// Over the pixels where either picture differs from `background` (the same scene without the character):
// how many, and how many of them agree within 2/255 and within 24/255.
struct CharacterAgreement {
    std::size_t pixels = 0, within2 = 0, within24 = 0;
    double share2() const { return double(within2) / double(pixels ? pixels : 1); }
    double share24() const { return double(within24) / double(pixels ? pixels : 1); }
};
CharacterAgreement characterAgreement(const app::Rgba8Image& a, const app::Rgba8Image& b, const app::Rgba8Image& background);
// A camera looking at a model standing at the origin, slightly from above, so that its pose sphere is
// `across` pixels wide in a view 120 pixels tall.
render::Camera cameraSeeingSphereAcross(const model::SkinnedModel& model, float across);
// Keeps a hardware-raster and a compute-raster picture for a look (artifactPath(name + "-hardware.png"), ...).
void keepRasterImages(const std::string& name, const app::Rgba8Image& hardware, const app::Rgba8Image& compute);

// A crowd of two models side by side against the same characters drawn as two one-model crowds and as
// an empty scene: pixels that only the first (second) crowd covers, and the fraction of the mixed
// image's pixels that equal the one-model crowds' (within 2/255). The second model's characters are
// scaled by `scaleB`. Leaves the images in artifactPath(name + "-*.png") when they do not match.
struct MixedCrowdMatch {
    std::size_t firstModelPixels = 0;
    std::size_t secondModelPixels = 0;
    double matchingFraction = 0.0;        // of all pixels
    double firstModelMatching = 0.0;      // of the first model's pixels
    double secondModelMatching = 0.0;     // of the second model's pixels
};
MixedCrowdMatch compareMixedCrowd(const app::HostDevice& context, const model::SkinnedModel& a,
                                  const model::SkinnedModel& b, float scaleB, const std::string& name);

// Where failing image tests leave their images for a person to look at.
std::string artifactPath(const std::string& name);

}  // namespace test
