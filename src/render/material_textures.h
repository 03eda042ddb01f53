#pragma once
// The base-colour textures of a crowd's models, in slots of one descriptor array. Slot 0 is a 1x1
// white texture, which models without a texture (and unused slots) point at, so every shader
// samples the same way.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/image.h"
#include "gpu_types.h"
#include "model/skinned_model.h"

namespace gpu { class VulkanContext; }

namespace render {

class MaterialTextures {
public:
    // Throws gpu::Error when more than MAX_TEXTURES - 1 models have a texture.
    MaterialTextures(const gpu::VulkanContext& context, std::span<const model::SkinnedModel* const> models);
    ~MaterialTextures();
    MaterialTextures(const MaterialTextures&) = delete;
    MaterialTextures& operator=(const MaterialTextures&) = delete;

    // The slot of model m's texture (0, white, when it has none).
    std::uint32_t slotOf(std::uint32_t model) const { return slots_[model]; }
    // One view per slot; slots past the last texture repeat the white one.
    std::array<VkImageView, MAX_TEXTURES> views() const;
    VkSampler sampler() const { return sampler_; }
    VkDeviceSize bytes() const;

private:
    void upload(const gpu::Image& image, std::span<const std::uint8_t> pixels);
    void release();

    const gpu::VulkanContext& context_;
    std::vector<gpu::Image> images_;
    std::vector<std::uint32_t> slots_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace render
