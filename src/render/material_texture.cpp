#include "render/material_texture.h"

#include <cstring>
#include <vector>

#include "gpu/barriers.h"
#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

MaterialTexture::MaterialTexture(const gpu::VulkanContext& context, const model::SkinnedModel& model)
    : context_(context) {
    const model::SkinnedModel::Texture& texture = model.baseColorTexture;
    const bool hasTexture = texture.width > 0 && texture.height > 0 && !texture.rgba.empty();
    const VkExtent2D extent = hasTexture ? VkExtent2D{texture.width, texture.height} : VkExtent2D{1, 1};
    const std::vector<std::uint8_t> white(4, 255);
    const std::vector<std::uint8_t>& pixels = hasTexture ? texture.rgba : white;

    std::vector<glm::vec2> uvs = model.uvs;
    uvs.resize(model.vertices.size(), glm::vec2(0.0f));
    if (uvs.empty()) uvs.emplace_back(0.0f);
    uvs_ = gpu::createBufferWithData(context, std::as_bytes(std::span(uvs)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     "texture coordinates");

    // glTF stores base colour in sRGB: an sRGB view makes the sampler return linear colour.
    image_ = gpu::createImage2D(context, extent, VK_FORMAT_R8G8B8A8_SRGB,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, "base-colour texture");
    gpu::Buffer staging = gpu::createBuffer(context, pixels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                            gpu::MemoryUse::HostUpload, "base-colour texture (staging)");
    std::memcpy(staging.mapped, pixels.data(), pixels.size());
    gpu::runOneShot(context, [&](VkCommandBuffer cmd) {
        gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_COLOR_BIT, {VK_PIPELINE_STAGE_2_NONE, 0},
                          {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT}, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer, image_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_COLOR_BIT,
                          {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                          {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    });
    gpu::destroyBuffer(context, staging);

    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    VK_CHECK(vkCreateSampler(context.device, &info, nullptr, &sampler_));
}

MaterialTexture::~MaterialTexture() {
    vkDestroySampler(context_.device, sampler_, nullptr);
    gpu::destroyBuffer(context_, uvs_);
    gpu::destroyImage(context_, image_);
}

}  // namespace render
