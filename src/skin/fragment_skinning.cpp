#include "skin/fragment_skinning.h"

#include <algorithm>

#include "gpu/barriers.h"
#include "gpu/gpu_timer.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "render/crowd_buffers.h"
#include "skin_fragment.frag.spv.h"
#include "skin_fragment.vert.spv.h"

namespace skin {

namespace {
constexpr VkFormat kTargetFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkDeviceSize kTexelBytes = 16;
}  // namespace

FragmentSkinning::FragmentSkinning(const MethodSetup& setup)
    : context_(setup.context), crowd_(setup.crowd) {
    layout_ = planSkinTargets(crowd_.vertexCount(), crowd_.characterCount(),
                              maxSkinTargetDimension(context_, setup.maxTargetDimension));
    try {
        for (std::uint32_t t = 0; t < layout_.tileCount; ++t) {
            const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
            Tile tile;
            tile.position = gpu::createImage2D(context_, layout_.tileExtent(t), kTargetFormat, usage,
                                               "skinned positions (RGBA32F target)");
            tiles_.push_back(tile);
            tiles_.back().normal = gpu::createImage2D(context_, layout_.tileExtent(t), kTargetFormat, usage,
                                                      "skinned normals (RGBA32F target)");
        }
        skinned_ = std::make_unique<SkinnedVertexBuffer>(context_, layout_.characterCount, layout_.characterStride(),
                                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        createPipeline();
        draw_ = std::make_unique<SkinnedDraw>(setup, layout_.characterStride());
    } catch (...) {
        release();
        throw;
    }
}

FragmentSkinning::~FragmentSkinning() { release(); }

void FragmentSkinning::release() {
    draw_.reset();
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (pipelineLayout_) vkDestroyPipelineLayout(context_.device, pipelineLayout_, nullptr);
    pipeline_ = VK_NULL_HANDLE, pipelineLayout_ = VK_NULL_HANDLE;
    descriptors_.reset();
    skinned_.reset();
    for (Tile& tile : tiles_) {
        gpu::destroyImage(context_, tile.normal);
        gpu::destroyImage(context_, tile.position);
    }
    tiles_.clear();
}

void FragmentSkinning::createPipeline() {
    const gpu::BufferBinding bindings[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd_.bindVertices().buffer},
                                            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd_.bones().buffer}};
    descriptors_ = std::make_unique<gpu::DescriptorBundle>(context_, VK_SHADER_STAGE_FRAGMENT_BIT, bindings);
    const VkDescriptorSetLayout setLayout = descriptors_->layout();
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(gpu::SkinPassParams)};
    pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout, 1}, {&push, 1});
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = skin_fragment_vert_spv;
    desc.fragmentShader = skin_fragment_frag_spv;
    desc.colorFormats = {kTargetFormat, kTargetFormat};
    desc.layout = pipelineLayout_;
    desc.cullMode = VK_CULL_MODE_NONE;
    pipeline_ = gpu::createGraphicsPipeline(context_, desc);
}

void FragmentSkinning::recordTile(VkCommandBuffer cmd, std::uint32_t t) {
    const Tile& tile = tiles_[t];
    for (VkImage image : {tile.position.image, tile.normal.image}) {
        // The previous frame's copy must have read the image before this frame overwrites it.
        gpu::imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, {VK_PIPELINE_STAGE_2_COPY_BIT, 0},
                          {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                          VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    }
    VkRenderingAttachmentInfo attachments[2] = {{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO},
                                                {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO}};
    const VkImageView views[2] = {tile.position.view, tile.normal.view};
    for (int i = 0; i < 2; ++i) {
        attachments[i].imageView = views[i];
        attachments[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        attachments[i].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every texel is written
        attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    }
    const VkExtent2D extent = layout_.tileExtent(t);
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, extent};
    info.layerCount = 1;
    info.colorAttachmentCount = 2;
    info.pColorAttachments = attachments;
    vkCmdBeginRendering(cmd, &info);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDescriptorSet set = descriptors_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set, 0, nullptr);
    gpu::setViewportAndScissor(cmd, extent);
    const gpu::SkinPassParams params = skinPassParams(layout_, t, crowd_.boneStride());
    vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof params, &params);
    vkCmdDraw(cmd, 3, 1, 0, 0);  // the full-target triangle
    vkCmdEndRendering(cmd);
}

void FragmentSkinning::recordCopies(VkCommandBuffer cmd) {
    for (const Tile& tile : tiles_)
        for (VkImage image : {tile.position.image, tile.normal.image})
            gpu::imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                              {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                              {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    const gpu::Access copyWrite{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    skinned_->barrierBeforeWrite(cmd, copyWrite);
    const VkDeviceSize normalsOffset = skinned_->streamBytes();
    for (std::uint32_t t = 0; t < layout_.tileCount; ++t) {
        VkBufferImageCopy region{};
        region.bufferOffset =
            static_cast<VkDeviceSize>(layout_.firstCharacter(t)) * layout_.characterStride() * kTexelBytes;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        const VkExtent2D extent = layout_.tileExtent(t);
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, tiles_[t].position.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               skinned_->buffer(), 1, &region);
        region.bufferOffset += normalsOffset;
        vkCmdCopyImageToBuffer(cmd, tiles_[t].normal.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, skinned_->buffer(),
                               1, &region);
    }
    skinned_->barrierAfterWrite(cmd, copyWrite);
}

void FragmentSkinning::recordSkinning(VkCommandBuffer cmd, gpu::GpuTimer& timer) {
    for (std::uint32_t t = 0; t < layout_.tileCount; ++t) recordTile(cmd, t);
    timer.mark(cmd, "skin");
    recordCopies(cmd);
    timer.mark(cmd, "copy");
}

void FragmentSkinning::recordDraw(VkCommandBuffer cmd, VkDescriptorSet sceneSet, const render::ScenePush& push) {
    draw_->record(cmd, sceneSet, push, skinnedVertices());
}

SkinnedVertices FragmentSkinning::skinnedVertices() const { return skinned_->vertices(); }

std::vector<MemoryItem> FragmentSkinning::memory() const {
    VkDeviceSize images = 0;
    for (const Tile& tile : tiles_) images += tile.position.bytes + tile.normal.bytes;
    return {{"RGBA32F skinning targets", images},
            {"skinned vertex buffer", skinned_->bytes()},
            {"draw commands", draw_->indirectBytes()}};
}

}  // namespace skin
