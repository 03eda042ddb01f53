#pragma once
// A model's base-colour texture and per-vertex texture coordinates on the GPU. Models without a
// texture get a 1x1 white one, so every shader samples the same way.
#include <vulkan/vulkan.h>

#include "gpu/buffer.h"
#include "gpu/image.h"
#include "model/skinned_model.h"

namespace gpu { class VulkanContext; }

namespace render {

class MaterialTexture {
public:
    MaterialTexture(const gpu::VulkanContext& context, const model::SkinnedModel& model);
    ~MaterialTexture();
    MaterialTexture(const MaterialTexture&) = delete;
    MaterialTexture& operator=(const MaterialTexture&) = delete;

    VkImageView view() const { return image_.view; }
    VkSampler sampler() const { return sampler_; }
    // One vec2 per model vertex (zeros when the model has none).
    const gpu::Buffer& uvs() const { return uvs_; }
    VkDeviceSize bytes() const { return image_.bytes + uvs_.size; }

private:
    const gpu::VulkanContext& context_;
    gpu::Image image_;
    gpu::Buffer uvs_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace render
