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

std::uint32_t maxSkinTargetDimension(const gpu::VulkanContext& context, std::uint32_t requested) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    const std::uint32_t device =
        std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxFramebufferHeight});
    return requested ? std::min(requested, device) : device;
}

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
        const VkDeviceSize streamBytes =
            static_cast<VkDeviceSize>(layout_.characterCount) * layout_.characterStride() * kTexelBytes;
        skinned_ = gpu::createBuffer(context_, 2 * streamBytes,
                                     VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                     gpu::MemoryUse::DeviceLocal, "skinned vertex buffer");
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
    if (pool_) vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
    pipeline_ = VK_NULL_HANDLE, pipelineLayout_ = VK_NULL_HANDLE, pool_ = VK_NULL_HANDLE, setLayout_ = VK_NULL_HANDLE;
    gpu::destroyBuffer(context_, skinned_);
    for (Tile& tile : tiles_) {
        gpu::destroyImage(context_, tile.normal);
        gpu::destroyImage(context_, tile.position);
    }
    tiles_.clear();
}

void FragmentSkinning::createPipeline() {
    const VkDescriptorSetLayoutBinding bindings[2] = {
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
    setLayout_ = gpu::createSetLayout(context_, bindings);
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
    pool_ = gpu::createDescriptorPool(context_, {&size, 1}, 1);
    set_ = gpu::allocateSet(context_, pool_, setLayout_);
    gpu::writeBufferDescriptor(context_, set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd_.bindVertices().buffer, 0,
                               VK_WHOLE_SIZE);
    gpu::writeBufferDescriptor(context_, set_, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, crowd_.bones().buffer, 0,
                               VK_WHOLE_SIZE);
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(gpu::SkinPassParams)};
    pipelineLayout_ = gpu::createPipelineLayout(context_, {&setLayout_, 1}, {&push, 1});
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
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout_, 0, 1, &set_, 0, nullptr);
    gpu::setViewportAndScissor(cmd, extent);
    gpu::SkinPassParams params{};
    params.counts = {layout_.charactersInTile(t), layout_.vertexCount, layout_.rowsPerCharacter,
                     layout_.firstCharacter(t)};
    params.strides = {layout_.width, crowd_.boneStride(), 0, 0};
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
    // The previous frame's draw must have read the vertex buffer before the copy overwrites it.
    gpu::bufferBarrier(cmd, skinned_.buffer, {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, 0},
                       {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkDeviceSize normalsOffset = skinnedVertices().normalsOffset;
    for (std::uint32_t t = 0; t < layout_.tileCount; ++t) {
        VkBufferImageCopy region{};
        region.bufferOffset =
            static_cast<VkDeviceSize>(layout_.firstCharacter(t)) * layout_.characterStride() * kTexelBytes;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        const VkExtent2D extent = layout_.tileExtent(t);
        region.imageExtent = {extent.width, extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, tiles_[t].position.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, skinned_.buffer, 1,
                               &region);
        region.bufferOffset += normalsOffset;
        vkCmdCopyImageToBuffer(cmd, tiles_[t].normal.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, skinned_.buffer, 1,
                               &region);
    }
    gpu::bufferBarrier(cmd, skinned_.buffer, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT});
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

SkinnedVertices FragmentSkinning::skinnedVertices() const {
    return {&skinned_, skinned_.size / 2, layout_.characterStride()};
}

std::vector<MemoryItem> FragmentSkinning::memory() const {
    VkDeviceSize images = 0;
    for (const Tile& tile : tiles_) images += tile.position.bytes + tile.normal.bytes;
    return {{"RGBA32F skinning targets", images},
            {"skinned vertex buffer", skinned_.size},
            {"draw commands", draw_->indirectBytes()}};
}

}  // namespace skin
