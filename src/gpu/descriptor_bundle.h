#pragma once
// One descriptor set of buffers with its own layout and pool: what each pass binds besides the scene.
#include <cstdint>
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

    // Points binding `index` at another buffer of the same type (a reallocated one). Only while no
    // command buffer that binds the set is pending or being recorded (between frames, the GPU idle).
    void rebind(std::uint32_t index, const BufferBinding& binding);

    VkDescriptorSetLayout layout() const { return layout_; }
    VkDescriptorSet set() const { return set_; }

private:
    const VulkanContext& context_;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace gpu
