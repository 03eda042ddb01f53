#include "render/material_textures.h"

#include <cstring>
#include <string>

#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {
namespace {

bool hasTexture(const model::SkinnedModel& model) {
    const model::SkinnedModel::Texture& t = model.baseColorTexture;
    return t.width > 0 && t.height > 0 && !t.rgba.empty();
}

}  // namespace

MaterialTextures::MaterialTextures(const gpu::VulkanContext& context, std::span<const model::SkinnedModel* const> models)
    : context_(context) {
    try {
        const std::uint8_t white[4] = {255, 255, 255, 255};
        // glTF stores base colour in sRGB: an sRGB view makes the sampler return linear colour.
        constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        images_.push_back(gpu::createImage2D(context, {1, 1}, VK_FORMAT_R8G8B8A8_SRGB, usage, "white texture"));
        upload(images_.back(), white);
        for (const model::SkinnedModel* model : models) {
            if (!hasTexture(*model)) {
                slots_.push_back(0);
                continue;
            }
            if (images_.size() >= MAX_TEXTURES)
                throw gpu::Error("a crowd's models may have at most " + std::to_string(MAX_TEXTURES - 1) +
                                 " base-colour textures (" + model->name + " would be one more)");
            const model::SkinnedModel::Texture& t = model->baseColorTexture;
            images_.push_back(gpu::createImage2D(context, {t.width, t.height}, VK_FORMAT_R8G8B8A8_SRGB, usage,
                                                 model->name + " base-colour texture"));
            upload(images_.back(), t.rgba);
            slots_.push_back(static_cast<std::uint32_t>(images_.size() - 1));
        }
        VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        info.magFilter = VK_FILTER_LINEAR;
        info.minFilter = VK_FILTER_LINEAR;
        info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        info.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
        VK_CHECK(vkCreateSampler(context.device, &info, nullptr, &sampler_));
    } catch (...) {
        release();
        throw;
    }
}

MaterialTextures::~MaterialTextures() { release(); }

void MaterialTextures::release() {
    if (sampler_) vkDestroySampler(context_.device, sampler_, nullptr);
    sampler_ = VK_NULL_HANDLE;
    for (gpu::Image& image : images_) gpu::destroyImage(context_, image);
    images_.clear();
}

void MaterialTextures::upload(const gpu::Image& image, std::span<const std::uint8_t> pixels) {
    gpu::Buffer staging = gpu::createBuffer(context_, pixels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                            gpu::MemoryUse::HostUpload, "base-colour texture (staging)");
    std::memcpy(staging.mapped, pixels.data(), pixels.size());
    const VkImage target = image.image;
    const VkExtent2D extent = image.extent;
    const VkBuffer source = staging.buffer;
    const gpu::VulkanContext& context = context_;
    gpu::runOneShot(context_, [=](VkCommandBuffer cmd) {
        gpu::imageBarrier(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, {VK_PIPELINE_STAGE_2_NONE, 0},
                          {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT}, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyBufferToImage(cmd, source, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        gpu::imageBarrier(cmd, target, VK_IMAGE_ASPECT_COLOR_BIT,
                          {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                          {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }, [&context, staging]() mutable { gpu::destroyBuffer(context, staging); });
}

std::array<VkImageView, MAX_TEXTURES> MaterialTextures::views() const {
    std::array<VkImageView, MAX_TEXTURES> views;
    for (std::size_t i = 0; i < views.size(); ++i) views[i] = images_[i < images_.size() ? i : 0].view;
    return views;
}

VkDeviceSize MaterialTextures::bytes() const {
    VkDeviceSize total = 0;
    for (const gpu::Image& image : images_) total += image.bytes;
    return total;
}

}  // namespace render
