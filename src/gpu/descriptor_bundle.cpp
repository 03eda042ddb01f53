#include "gpu/descriptor_bundle.h"

#include <vector>

#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"

namespace gpu {

DescriptorBundle::DescriptorBundle(const VulkanContext& context, VkShaderStageFlags stages,
                                   std::span<const BufferBinding> bindings)
    : context_(context) {
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    std::vector<VkDescriptorPoolSize> sizes;
    for (std::uint32_t i = 0; i < bindings.size(); ++i) {
        layoutBindings.push_back({i, bindings[i].type, 1, stages, nullptr});
        sizes.push_back({bindings[i].type, 1});
    }
    layout_ = createSetLayout(context, layoutBindings);
    pool_ = createDescriptorPool(context, sizes, 1);
    set_ = allocateSet(context, pool_, layout_);
    for (std::uint32_t i = 0; i < bindings.size(); ++i)
        writeBufferDescriptor(context, set_, i, bindings[i].type, bindings[i].buffer, bindings[i].offset,
                              bindings[i].range);
}

void DescriptorBundle::rebind(std::uint32_t index, const BufferBinding& binding) {
    writeBufferDescriptor(context_, set_, index, binding.type, binding.buffer, binding.offset, binding.range);
}

DescriptorBundle::~DescriptorBundle() {
    vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    vkDestroyDescriptorSetLayout(context_.device, layout_, nullptr);
}

}  // namespace gpu
