#pragma once
// One descriptor set of buffers with its own layout and pool: what each pass binds besides the scene.
#include <span>

#include <vulkan/vulkan.h>

namespace gpu {

class VulkanContext;

struct BufferBinding {
    VkDescriptorType type;
    VkBuffer buffer;
    VkDeviceSize offset = 0;
    VkDeviceSize range = VK_WHOLE_SIZE;
};

class DescriptorBundle {
public:
    // Binding i of the set is bindings[i], visible to `stages`.
    DescriptorBundle(const VulkanContext& context, VkShaderStageFlags stages, std::span<const BufferBinding> bindings);
    ~DescriptorBundle();
    DescriptorBundle(const DescriptorBundle&) = delete;
    DescriptorBundle& operator=(const DescriptorBundle&) = delete;

    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set() const { return set_; }

private:
    const VulkanContext& context_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace gpu
