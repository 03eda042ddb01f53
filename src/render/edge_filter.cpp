#include "render/edge_filter.h"

#include "edge_filter.comp.spv.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {
namespace {

// The shader's workgroup (local_size_x, local_size_y).
constexpr std::uint32_t kGroupWidth = 16;
constexpr std::uint32_t kGroupHeight = 8;

struct Push {
    std::int32_t width;
    std::int32_t height;
};

}  // namespace

bool isSrgbFormat(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_SRGB:
        case VK_FORMAT_R8G8_SRGB:
        case VK_FORMAT_R8G8B8_SRGB:
        case VK_FORMAT_B8G8R8_SRGB:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_A8B8G8R8_SRGB_PACK32: return true;
        default: return false;
    }
}

EdgeFilter::EdgeFilter(const gpu::VulkanContext& context, bool encodeSrgb, std::uint32_t slots) : context_(context) {
    try {
        // Linear, clamped: the shader samples half way between pixels to average them.
        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        VK_CHECK(vkCreateSampler(context.device, &samplerInfo, nullptr, &sampler_));

        const VkDescriptorSetLayoutBinding bindings[2] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        setLayout_ = gpu::createSetLayout(context, bindings);
        const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, slots},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, slots}};
        pool_ = gpu::createDescriptorPool(context, sizes, slots);
        for (std::uint32_t slot = 0; slot < slots; ++slot) sets_.push_back(gpu::allocateSet(context, pool_, setLayout_));
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
        layout_ = gpu::createPipelineLayout(context, {&setLayout_, 1}, {&push, 1});
        const std::uint32_t constants[1] = {encodeSrgb ? 1u : 0u};
        pipeline_ = gpu::createComputePipeline(context, edge_filter_comp_spv, layout_, constants);
    } catch (...) {
        release();
        throw;
    }
}

EdgeFilter::~EdgeFilter() { release(); }

// Only from the destructor, or the constructor as it throws: nothing uses the handles after it.
void EdgeFilter::release() {
    vkDestroyPipeline(context_.device, pipeline_, nullptr);  // a null handle is ignored
    vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);  // frees the sets
    vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
    vkDestroySampler(context_.device, sampler_, nullptr);
}

void EdgeFilter::record(VkCommandBuffer cmd, std::uint32_t slot, VkImageView source, VkImageView destination,
                        VkExtent2D extent) const {
    // The slot's previous frame is done (the host's promise): its set may be rewritten.
    gpu::writeImageDescriptor(context_, sets_[slot], 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sampler_, source,
                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    gpu::writeImageDescriptor(context_, sets_[slot], 1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_NULL_HANDLE, destination,
                              VK_IMAGE_LAYOUT_GENERAL);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[slot], 0, nullptr);
    const Push push{static_cast<std::int32_t>(extent.width), static_cast<std::int32_t>(extent.height)};
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, (extent.width + kGroupWidth - 1) / kGroupWidth, (extent.height + kGroupHeight - 1) / kGroupHeight, 1);
}

}  // namespace render
