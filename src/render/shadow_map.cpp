#include "render/shadow_map.h"

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace render {

glm::vec3 lightDirection() { return glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f)); }

ShadowMap::ShadowMap(const gpu::VulkanContext& context, std::uint32_t size) : context_(context) {
    image_ = gpu::createImage2D(context, {size, size}, kShadowFormat,
                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT |  // read back by tests
                                    VK_IMAGE_USAGE_TRANSFER_DST_BIT,   // the compute raster's depth
                                "shadow map");
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;  // outside the map: lit
    info.compareEnable = VK_TRUE;
    info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    const VkResult result = vkCreateSampler(context.device, &info, nullptr, &sampler_);
    if (result != VK_SUCCESS) {
        gpu::destroyImage(context, image_);
        VK_CHECK(result);
    }
}

ShadowMap::~ShadowMap() {
    vkDestroySampler(context_.device, sampler_, nullptr);
    gpu::destroyImage(context_, image_);
}

namespace {

void beginDepthRendering(VkCommandBuffer cmd, const gpu::Image& image, VkAttachmentLoadOp load) {
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = image.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = load;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, image.extent};
    info.layerCount = 1;
    info.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &info);
    gpu::setViewportAndScissor(cmd, image.extent);
}

// Who samples the map: the shading (fragment shaders) and the ground's sunlight pass (compute).
constexpr VkPipelineStageFlags2 kSamplers = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

constexpr gpu::Access kDepthAttachment{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT};

}  // namespace

void ShadowMap::beginRendering(VkCommandBuffer cmd) const {
    // The previous frame's shading must be done sampling before the map is drawn again.
    gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_DEPTH_BIT, {kSamplers, 0}, kDepthAttachment,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    beginDepthRendering(cmd, image_, VK_ATTACHMENT_LOAD_OP_CLEAR);
}

namespace {
constexpr gpu::Access kCopyWrite{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
}  // namespace

void ShadowMap::copyFrom(VkCommandBuffer cmd, VkBuffer depthBits) const {
    gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_DEPTH_BIT, {kSamplers, 0}, kCopyWrite,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.imageExtent = {image_.extent.width, image_.extent.height, 1};
    vkCmdCopyBufferToImage(cmd, depthBits, image_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

void ShadowMap::beginRenderingOver(VkCommandBuffer cmd) const {
    gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_DEPTH_BIT, kCopyWrite, kDepthAttachment,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    beginDepthRendering(cmd, image_, VK_ATTACHMENT_LOAD_OP_LOAD);
}

void ShadowMap::copyDone(VkCommandBuffer cmd) const {
    gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_DEPTH_BIT, kCopyWrite,
                      {kSamplers, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT}, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void ShadowMap::endRendering(VkCommandBuffer cmd) const {
    vkCmdEndRendering(cmd);
    gpu::imageBarrier(cmd, image_.image, VK_IMAGE_ASPECT_DEPTH_BIT,
                      {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT},
                      {kSamplers, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT}, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void ShadowMap::clear(VkCommandBuffer cmd) const {
    beginRendering(cmd);
    endRendering(cmd);
}

}  // namespace render
