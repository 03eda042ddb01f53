#pragma once
// The directional light's shadow map: a depth image the characters are drawn into from the light
// (consuming the same skinned vertices as the colour pass), sampled with depth comparison by the
// character and ground shading. It covers the camera's view out to a shadow distance in one to four
// cascades, each a square of it (render/shadow_cascades.h); beyond that nothing is shadowed.
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu/image.h"

namespace gpu { class VulkanContext; }

namespace render {

// 16 bits a texel: the depths a character's shadow is compared with are 1/65,536 of the light's depth
// range apart (a few millimetres over a crowd), far finer than the comparison's bias (0.0015 of it,
// render/scene_pass.h), and half the bytes of a 32-bit float to write, copy and sample. Measured on
// the H100: the compute rasterizer's copy into a 2048-texel map costs 0.096 ms against 0.184 for
// D32_SFLOAT (docs/gpu-driven-frame.md).
constexpr VkFormat kShadowFormat = VK_FORMAT_D16_UNORM;

// The light: a unit vector towards the sun (the lighting's), and the ambient term.
glm::vec3 lightDirection();

class ShadowMap {
public:
    ShadowMap(const gpu::VulkanContext& context, std::uint32_t size);
    ~ShadowMap();
    ShadowMap(const ShadowMap&) = delete;
    ShadowMap& operator=(const ShadowMap&) = delete;

    VkImage image() const { return image_.image; }
    VkImageView view() const { return image_.view; }
    VkSampler sampler() const { return sampler_; }
    std::uint32_t size() const { return image_.extent.width; }
    VkDeviceSize bytes() const { return image_.bytes; }
    // Begins depth-only rendering into the map, cleared to the far plane.
    void beginRendering(VkCommandBuffer cmd) const;
    // Copies a compute rasterizer's depth (kShadowFormat's texels, row-major) into the map: a copy,
    // not a full-screen pass writing gl_FragDepth, which on the H100 ran on the small graphics slice.
    // Then either beginRenderingOver (casters to draw on top) or copyDone (none).
    void copyFrom(VkCommandBuffer cmd, VkBuffer depthBits) const;
    // After copyFrom: begins depth-only rendering over the copied depth.
    void beginRenderingOver(VkCommandBuffer cmd) const;
    // After copyFrom, with nothing to draw on top: leaves the map ready to sample.
    void copyDone(VkCommandBuffer cmd) const;
    // Ends it and leaves the map ready for the fragment shaders to sample.
    void endRendering(VkCommandBuffer cmd) const;
    // Leaves a map that was never rendered ready to sample (shadows off: cleared, so all lit).
    void clear(VkCommandBuffer cmd) const;

private:
    const gpu::VulkanContext& context_;
    gpu::Image image_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace render
