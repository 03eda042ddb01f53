#pragma once
// What every method's draw shares: the per-frame scene uniforms (camera, light, shadow cascades), their
// descriptor set (with the pool's texture coordinates, textures and material table), the ground plane
// and the sky behind it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu_types.h"

#include "render/shadow_cascades.h"
#include "render/target_format.h"

namespace gpu { class VulkanContext; }

namespace render {

class GeometryPool;
class GroundSunlight;
class TerrainBuffer;
class ShadowMap;

// The clear colour behind everything and the colour distant things fade into (linear RGB).
inline constexpr glm::vec3 kSkyColor{0.55f, 0.7f, 0.9f};

// What the shading subtracts from a point's depth in the light before comparing it with the shadow map
// (SceneUniforms::shadow.y): against acne on lit surfaces.
inline constexpr float kShadowDepthBias = 0.0015f;

// Push constants of the ground and draw fragment shaders.
struct ScenePush {
    glm::vec4 cameraPosition;
    glm::vec4 groundArea;  // x, z: centre, w: half extent
};

// How the ground is drawn; the defaults are the renderer's, the others references for tests.
struct GroundOptions {
    bool filteredTiles = true;  // the tiles integrated over each pixel's footprint (false: point-sampled)
    bool sunlightImage = true;  // the ground sunlight image (false: nine shadow-map comparisons a pixel)
};

class ScenePass {
public:
    ScenePass(const gpu::VulkanContext& context, std::uint32_t framesInFlight, const GeometryPool& pool,
              const ShadowMap& shadowMap, const GroundSunlight& groundSunlight, const TerrainBuffer& terrain,
              const TargetFormat& target, GroundOptions ground = {});
    ~ScenePass();
    ScenePass(const ScenePass&) = delete;
    ScenePass& operator=(const ScenePass&) = delete;

    VkDescriptorSetLayout setLayout() const { return setLayout_; }
    VkDescriptorSet set(std::uint32_t frameSlot) const { return sets_[frameSlot]; }
    // The same layout seen from the light, one set for each shadow cascade: its uniforms' viewProjection
    // is the cascade's (the hardware shadow pass, render/shadow_cascades.h: ShadowCascades::mapClip).
    VkDescriptorSet lightSet(std::uint32_t frameSlot, std::uint32_t cascade) const {
        return sets_[lightIndex(frameSlot, cascade)];
    }
    void update(std::uint32_t frameSlot, const gpu::SceneUniforms& uniforms);
    void updateLight(std::uint32_t frameSlot, std::uint32_t cascade, const gpu::SceneUniforms& uniforms);
    // The ground as a quad at y = 0, or over `terrain` its grid (shaders/ground.vert.glsl).
    void recordGround(VkCommandBuffer cmd, std::uint32_t frameSlot, const ScenePush& push,
                      const gpu::TerrainGrid& terrain) const;
    // The sky colour (kSkyColor) on every pixel still at the cleared depth: after everything opaque, it
    // writes the pixels a colour clear would have, so the host need not clear its colour target. On an
    // H200's graphics slice (the H100's) a colour clear costs 0.15 ms a sample per pixel at 1080p; the
    // sky costs as much only where it shows (docs/gpu-driven-frame.md, "The sky instead of a colour
    // clear").
    void recordSky(VkCommandBuffer cmd, std::uint32_t frameSlot) const;

private:
    void writeTextures(VkDescriptorSet set, const GeometryPool& pool) const;
    std::size_t lightIndex(std::uint32_t frameSlot, std::uint32_t cascade) const {
        return framesInFlight_ + std::size_t{frameSlot} * kMostShadowCascades + cascade;
    }

    const gpu::VulkanContext& context_;
    std::uint32_t framesInFlight_ = 0;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<gpu::Buffer> uniforms_;
    std::vector<VkDescriptorSet> sets_;
    VkPipelineLayout groundLayout_ = VK_NULL_HANDLE;
    VkPipeline groundPipeline_ = VK_NULL_HANDLE;
    VkPipeline skyPipeline_ = VK_NULL_HANDLE;  // in groundLayout_, which its fragment shader's set fits
};

// Scene uniforms for a camera: sun from the upper left, pale sky, grass; and the shadow cascades'
// transforms (shadows off: `shadows` false). The materials are the pool's (GeometryPool::materials).
gpu::SceneUniforms makeSceneUniforms(const glm::mat4& viewProjection, float fogDensity,
                                     const ShadowCascades& cascades = {}, bool shadows = false,
                                     std::uint32_t shadowMapSize = 1);

}  // namespace render
