#pragma once
// Small free functions that create shader modules, layouts and graphics pipelines.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

VkShaderModule createShaderModule(const VulkanContext& context, std::span<const std::uint32_t> spirv);

VkDescriptorSetLayout createSetLayout(const VulkanContext& context,
                                      std::span<const VkDescriptorSetLayoutBinding> bindings);
VkPipelineLayout createPipelineLayout(const VulkanContext& context, std::span<const VkDescriptorSetLayout> sets,
                                      std::span<const VkPushConstantRange> pushConstants);

struct GraphicsPipelineDesc {
    std::span<const std::uint32_t> vertexShader;
    std::span<const std::uint32_t> fragmentShader;
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;  // no depth attachment when undefined
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // of the attachments it renders into
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
    // Depth bias (shadow maps): constant in depth units and per unit of slope; off when both are 0.
    float depthBiasConstant = 0.0f;
    float depthBiasSlope = 0.0f;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    // Specialization constants of the vertex stage, ids 0, 1, ... in order.
    std::vector<std::uint32_t> vertexConstants;
    // And of the fragment stage.
    std::vector<std::uint32_t> fragmentConstants;
    // The fragment's colour blended over the target's by its alpha (the target's alpha kept): a layer
    // covering parts of pixels (the far crowd's).
    bool blendOver = false;
    bool depthWrite = true;  // with a depth attachment: the depth test passes write the fragment's depth
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
};

// Viewport and scissor are dynamic; rendering uses dynamic rendering with the given formats.
VkPipeline createGraphicsPipeline(const VulkanContext& context, const GraphicsPipelineDesc& desc);

// A compute pipeline; `constants` are specialization constants with ids 0, 1, ... in order.
VkPipeline createComputePipeline(const VulkanContext& context, std::span<const std::uint32_t> spirv,
                                 VkPipelineLayout layout, std::span<const std::uint32_t> constants);

// A descriptor pool big enough for `sets` sets of the given descriptor counts.
VkDescriptorPool createDescriptorPool(const VulkanContext& context, std::span<const VkDescriptorPoolSize> sizes,
                                      std::uint32_t sets);
VkDescriptorSet allocateSet(const VulkanContext& context, VkDescriptorPool pool, VkDescriptorSetLayout layout);
void writeBufferDescriptor(const VulkanContext& context, VkDescriptorSet set, std::uint32_t binding,
                           VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range);
// One image (a combined image sampler: with its sampler; a storage image: sampler null) at `binding`.
void writeImageDescriptor(const VulkanContext& context, VkDescriptorSet set, std::uint32_t binding,
                          VkDescriptorType type, VkSampler sampler, VkImageView view, VkImageLayout layout);

void setViewportAndScissor(VkCommandBuffer cmd, VkExtent2D extent);
void setViewportAndScissor(VkCommandBuffer cmd, const VkRect2D& area);

}  // namespace gpu
