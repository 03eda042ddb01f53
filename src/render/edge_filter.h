#pragma once
// The edge filter (crowdgpu::RendererSettings::edgeFilter): anti-aliasing of the host's finished picture
// in compute, FXAA-like (shaders/edge_filter.comp.glsl). It reads one image the host lends and writes
// another; the host owns both, their layouts and the barriers around the pass.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace gpu { class VulkanContext; }

namespace render {

// Whether a colour format stores sRGB-encoded values (the filter then encodes what it writes through
// the destination's UNORM view).
bool isSrgbFormat(VkFormat format);

class EdgeFilter {
public:
    // `encodeSrgb`: destinations are UNORM views of sRGB images. One descriptor set per frame slot.
    EdgeFilter(const gpu::VulkanContext& context, bool encodeSrgb, std::uint32_t slots);
    ~EdgeFilter();
    EdgeFilter(const EdgeFilter&) = delete;
    EdgeFilter& operator=(const EdgeFilter&) = delete;

    // `source` sampled (SHADER_READ_ONLY_OPTIMAL), `destination` an R8G8B8A8_UNORM storage view
    // (GENERAL), both `extent`. Rewrites the slot's set: once per slot a frame, its previous frame done.
    void record(VkCommandBuffer cmd, std::uint32_t slot, VkImageView source, VkImageView destination,
                VkExtent2D extent) const;

private:
    void release();

    const gpu::VulkanContext& context_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> sets_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace render
