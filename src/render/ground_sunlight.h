#pragma once
// The ground's sunlight in the light's space (issue 18, "shadows that cost what they show"): a mipmapped
// RGBA8 image (red used) the size of the shadow map holding, per texel, the filtered shadow-map comparison at the
// ground point under it, made in compute after the shadow pass (shaders/ground_sunlight.comp.glsl).
// The ground's fragment shader fetches it once, trilinearly, where it made nine comparisons: on the H100
// those comparisons over a full screen of ground cost 0.38 ms of the graphics slice at paper-fig4.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

namespace gpu { class VulkanContext; }

namespace render {

class ShadowMap;

class GroundSunlight {
public:
    GroundSunlight(const gpu::VulkanContext& context, const ShadowMap& map);
    // Its texels' bytes for a map of `size` texels a side (the memory plan's estimate).
    static std::uint64_t bytesFor(std::uint32_t size);
    ~GroundSunlight();
    GroundSunlight(const GroundSunlight&) = delete;
    GroundSunlight& operator=(const GroundSunlight&) = delete;

    // After the shadow map is drawn and ready to sample (ShadowMap::endRendering): every level, left
    // ready for the fragment shaders. `depthBias` and `texel` as SceneUniforms::shadow's y and z.
    void record(VkCommandBuffer cmd, const glm::mat4& lightViewProjection, float depthBias, float texel) const;
    // Shadows off: all lit, ready to sample (bound to the ground's pipeline, never read).
    void recordAllLit(VkCommandBuffer cmd) const;
    VkImageView view() const { return view_; }
    VkSampler sampler() const { return sampler_; }
    std::uint32_t levels() const { return levels_; }
    VkDeviceSize bytes() const { return bytes_; }

private:
    void release();

    const gpu::VulkanContext& context_;
    std::uint32_t size_ = 0;
    std::uint32_t levels_ = 0;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize bytes_ = 0;
    VkImageView view_ = VK_NULL_HANDLE;             // every level, sampled by the ground
    std::vector<VkImageView> levelViews_;           // one level each, written
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
