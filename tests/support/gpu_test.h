#pragma once
// Test support for GPU tests: a Vulkan context with the Khronos validation layer and
// synchronization validation; any validation message during a test fails it.
#include <map>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "crowd/crowd.h"
#include "crowd/cull_reference.h"
#include "app/crowd_renderer.h"
#include "gpu/vulkan_context.h"
#include "render/png_writer.h"
#include "skin/skinning_method.h"

namespace test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::unique_ptr<gpu::VulkanContext> context;
};

// The world-space positions and normals (xyz, w as written) of one character, read back from the GPU.
struct ReadbackVertices {
    std::vector<glm::vec4> positions;
    std::vector<glm::vec4> normals;
};
ReadbackVertices readSkinnedVertices(const gpu::VulkanContext& context, const render::SkinnedVertices& vertices,
                                     std::uint32_t firstVertex, std::uint32_t vertexCount);

// A device buffer's bytes, copied to the host.
std::vector<std::byte> readBuffer(const gpu::VulkanContext& context, const gpu::Buffer& buffer);

// The last frame's visible lists, per bucket, sorted (the GPU's atomics append in any order).
crowd::VisibleLists readVisibleLists(const gpu::VulkanContext& context, const app::CrowdRenderer& renderer);
// The last frame's impostor list (impostor-level and demoted characters in view), sorted.
std::vector<std::uint32_t> readImpostorList(const gpu::VulkanContext& context, const app::CrowdRenderer& renderer);
// The character records the GPU culled from in the last frame (the motion pass writes them).
std::vector<gpu::CharacterRecord> readCharacterRecords(const gpu::VulkanContext& context,
                                                       const app::CrowdRenderer& renderer);

// One character in the last frame's draw list: its level of detail and its skinned vertices.
struct DrawnCharacter {
    std::uint32_t lod = 0;
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
};
// The last frame's compacted draw list, by character (culled characters are absent); call after finish().
std::map<std::uint32_t, DrawnCharacter> readDrawList(const gpu::VulkanContext& context,
                                                     const app::CrowdRenderer& renderer);

// The last frame's skinned vertices of one drawn character (it must be in the draw list).
ReadbackVertices readSkinnedCharacter(const gpu::VulkanContext& context, app::CrowdRenderer& renderer,
                                      std::uint32_t character);

// Fraction of pixels whose every channel differs by at most `tolerance` (out of 255).
double fractionOfMatchingPixels(const render::Rgba8Image& a, const render::Rgba8Image& b, int tolerance);

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
MixedCrowdMatch compareMixedCrowd(const gpu::VulkanContext& context, const model::SkinnedModel& a,
                                  const model::SkinnedModel& b, float scaleB, const std::string& name);

// Where failing image tests leave their images for a person to look at.
std::string artifactPath(const std::string& name);

}  // namespace test
