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
struct ShadowCascades;

class GroundSunlight {
public:
    GroundSunlight(const gpu::VulkanContext& context, const ShadowMap& map);
    // Its texels' bytes for a map of `size` texels a side (the memory plan's estimate).
    static std::uint64_t bytesFor(std::uint32_t size);
    ~GroundSunlight();
    GroundSunlight(const GroundSunlight&) = delete;
    GroundSunlight& operator=(const GroundSunlight&) = delete;

    // The first level worth making for a viewport: the map's resolution, or up to three levels below it
    // while that still has two texels a pixel along the viewport's longer side (a small viewport cannot
    // show more, and on a CPU rasterizer the full level costs most of the frame). The ground never
    // samples finer than it (SceneUniforms::shadow.w).
    std::uint32_t firstLevel(VkExtent2D viewport) const;
    // After the shadow map is drawn and ready to sample (ShadowMap::endRendering): the first level and the
    // four below it, each cascade's square from its own transform, left ready for the fragment shaders.
    // `depthBias` and `texel` as SceneUniforms::shadow's y and z.
    void record(VkCommandBuffer cmd, const ShadowCascades& cascades, float depthBias, float texel,
                std::uint32_t firstLevel) const;
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
    std::vector<VkDescriptorSet> sets_;  // one for each first level
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
