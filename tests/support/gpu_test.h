#pragma once
// Test support for GPU tests: a Vulkan context with the Khronos validation layer and
// synchronization validation; any validation message during a test fails it.
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "crowd/crowd.h"
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
ReadbackVertices readSkinnedCharacter(const gpu::VulkanContext& context, const skin::SkinnedVertices& vertices,
                                      std::uint32_t character, std::uint32_t vertexCount);

// Fraction of pixels whose every channel differs by at most `tolerance` (out of 255).
double fractionOfMatchingPixels(const render::Rgba8Image& a, const render::Rgba8Image& b, int tolerance);

// Where failing image tests leave their images for a person to look at.
std::string artifactPath(const std::string& name);

}  // namespace test
