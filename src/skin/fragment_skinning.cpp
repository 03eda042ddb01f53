#include "skin/fragment_skinning.h"

#include "gpu/barriers.h"
#include "gpu/pass_observer.h"
#include "gpu/vulkan_context.h"
#include "render/draw_lists.h"
#include "skin_fragment.frag.spv.h"

namespace skin {

namespace {
constexpr VkFormat kTargetFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkDeviceSize kTexelBytes = 16;
}  // namespace

FragmentSkinning::FragmentSkinning(const MethodSetup& setup) : context_(setup.context) {
    try {
        skinned_ = std::make_unique<SkinnedVertexBuffer>(context_, setup.lists.skinnedCapacity(),
                                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        pass_ = std::make_unique<FragmentSkinPass>(setup, *skinned_, skin_fragment_frag_spv,
                                                   std::vector<VkFormat>{kTargetFormat, kTargetFormat});
        const SkinTargetLayout& layout = pass_->layout();
        const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        for (std::uint32_t t = 0; t < layout.tileCount; ++t) {
            tiles_.emplace_back();
            tiles_.back().position = gpu::createImage2D(context_, layout.tileExtent(t), kTargetFormat, usage,
                                                        "skinned positions (RGBA32F target)");
            tiles_.back().normal = gpu::createImage2D(context_, layout.tileExtent(t), kTargetFormat, usage,
                                                      "skinned normals (RGBA32F target)");
        }
    } catch (...) {
        release();
        throw;
    }
}

FragmentSkinning::~FragmentSkinning() { release(); }

void FragmentSkinning::release() {
    for (Tile& tile : tiles_) {
        gpu::destroyImage(context_, tile.normal);
        gpu::destroyImage(context_, tile.position);
    }
    tiles_.clear();
    pass_.reset();
    skinned_.reset();
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
        // Texels no visible character owns are copied but never drawn: no clear needed.
        attachments[i].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        attachments[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    }
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, pass_->layout().tileExtent(t)};
    info.layerCount = 1;
    info.colorAttachmentCount = 2;
    info.pColorAttachments = attachments;
    vkCmdBeginRendering(cmd, &info);
    pass_->recordTile(cmd, t);
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
    const SkinTargetLayout& layout = pass_->layout();
    const VkDeviceSize normalsOffset = skinned_->streamBytes();
    for (std::uint32_t t = 0; t < layout.tileCount; ++t) {
        const VkExtent2D extent = layout.tileExtent(t);
        // The last tile's last row may run past the buffer's slots: copy whole rows only up to it.
        const std::uint64_t firstSlot = static_cast<std::uint64_t>(layout.firstRow(t)) * layout.width;
        const std::uint64_t slots = std::min<std::uint64_t>(static_cast<std::uint64_t>(extent.height) * layout.width,
                                                            layout.capacity - firstSlot);
        const std::uint32_t fullRows = static_cast<std::uint32_t>(slots / layout.width);
        const std::uint32_t rest = static_cast<std::uint32_t>(slots % layout.width);
        VkBufferImageCopy regions[2] = {};
        std::uint32_t regionCount = 0;
        if (fullRows > 0) {
            regions[regionCount].bufferOffset = firstSlot * kTexelBytes;
            regions[regionCount].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            regions[regionCount].imageExtent = {layout.width, fullRows, 1};
            ++regionCount;
        }
        if (rest > 0) {
            regions[regionCount].bufferOffset = (firstSlot + static_cast<std::uint64_t>(fullRows) * layout.width) * kTexelBytes;
            regions[regionCount].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            regions[regionCount].imageOffset = {0, static_cast<std::int32_t>(fullRows), 0};
            regions[regionCount].imageExtent = {rest, 1, 1};
            ++regionCount;
        }
        vkCmdCopyImageToBuffer(cmd, tiles_[t].position.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, skinned_->buffer(),
                               regionCount, regions);
        for (std::uint32_t r = 0; r < regionCount; ++r) regions[r].bufferOffset += normalsOffset;
        vkCmdCopyImageToBuffer(cmd, tiles_[t].normal.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, skinned_->buffer(),
                               regionCount, regions);
    }
    skinned_->barrierAfterWrite(cmd, copyWrite);
}

void FragmentSkinning::recordSkinning(VkCommandBuffer cmd, const gpu::PassObserver& passes) {
    for (std::uint32_t t = 0; t < pass_->layout().tileCount; ++t) recordTile(cmd, t);
    gpu::passDone(passes, cmd, "skin");
    recordCopies(cmd);
    gpu::passDone(passes, cmd, "copy");
}

std::vector<MemoryItem> FragmentSkinning::memory() const {
    VkDeviceSize images = 0;
    for (const Tile& tile : tiles_) images += tile.position.bytes + tile.normal.bytes;
    return {{"RGBA32F skinning targets", images}, {"skinned vertex buffer", skinned_->bytes()}};
}

}  // namespace skin
