#include "render/ground_sunlight.h"

#include <algorithm>
#include <bit>

#include "ground_sunlight.comp.spv.h"
#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/shadow_cascades.h"
#include "render/shadow_map.h"

namespace render {
namespace {

// RGBA8, not R8: rgba8 is a storage format every device has; r8 needs shaderStorageImageExtendedFormats,
// a feature the host would have to enable on the device it lends.
constexpr VkFormat kFormat = VK_FORMAT_R8G8B8A8_UNORM;

// A first level and four halvings, made by one dispatch (16x16 blocks in shared memory): a pixel whose
// footprint spans up to 16 texels of the first level averages them; beyond, on the farthest ground, it
// aliases.
constexpr std::uint32_t kLevelsADispatch = 5;
// The first level is at most this far below the map's resolution (for small viewports).
constexpr std::uint32_t kMostFirstLevel = 3;

std::uint32_t levelsFor(std::uint32_t size) {
    return std::min(kMostFirstLevel + kLevelsADispatch, static_cast<std::uint32_t>(std::bit_width(size)));
}

struct Push {
    glm::mat4 lightViewProjection;
    glm::vec4 shadow;
    std::uint32_t size;
    std::uint32_t levels;
    float step;
    std::uint32_t side;
    glm::uvec2 origin;
};

VkImageView createView(const gpu::VulkanContext& context, VkImage image, std::uint32_t firstLevel,
                       std::uint32_t levels) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = kFormat;
    info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, firstLevel, levels, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(context.device, &info, nullptr, &view));
    return view;
}


}  // namespace

GroundSunlight::GroundSunlight(const gpu::VulkanContext& context, const ShadowMap& map)
    : context_(context),
      size_(map.size()),
      levels_(levelsFor(map.size())) {
    try {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = kFormat;
        info.extent = {size_, size_, 1};
        info.mipLevels = levels_;
        info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        VK_CHECK(vkCreateImage(context.device, &info, nullptr, &image_));
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(context.device, image_, &requirements);
        bytes_ = requirements.size;
        memory_ = gpu::allocateMemory(context, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "ground sunlight");
        VK_CHECK(vkBindImageMemory(context.device, image_, memory_, 0));
        view_ = createView(context, image_, 0, levels_);
        for (std::uint32_t level = 0; level < levels_; ++level) levelViews_.push_back(createView(context, image_, level, 1));

        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
        samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
        samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        samplerInfo.maxLod = static_cast<float>(levels_ - 1);
        VK_CHECK(vkCreateSampler(context.device, &samplerInfo, nullptr, &sampler_));

        VkDescriptorSetLayoutBinding bindings[1 + kLevelsADispatch];
        bindings[0] = {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        for (std::uint32_t level = 0; level < kLevelsADispatch; ++level)
            bindings[1 + level] = {1 + level, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        setLayout_ = gpu::createSetLayout(context, bindings);
        // One set for each first level: its level and the four below it.
        const std::uint32_t firsts = std::min(kMostFirstLevel, levels_ - 1) + 1;
        const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, firsts},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kLevelsADispatch * firsts}};
        pool_ = gpu::createDescriptorPool(context, sizes, firsts);
        for (std::uint32_t first = 0; first < firsts; ++first) {
            const VkDescriptorSet set = gpu::allocateSet(context, pool_, setLayout_);
            gpu::writeImageDescriptor(context, set, 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, map.sampler(),
                                      map.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            // Past the image's last level, that level again (never written: `levels` stops short).
            for (std::uint32_t level = 0; level < kLevelsADispatch; ++level)
                gpu::writeImageDescriptor(context, set, 1 + level, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_NULL_HANDLE,
                                          levelViews_[std::min(first + level, levels_ - 1)], VK_IMAGE_LAYOUT_GENERAL);
            sets_.push_back(set);
        }
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
        layout_ = gpu::createPipelineLayout(context, {&setLayout_, 1}, {&push, 1});
        pipeline_ = gpu::createComputePipeline(context, ground_sunlight_comp_spv, layout_, {});
    } catch (...) {
        release();
        throw;
    }
    context.setDebugName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(image_), "ground sunlight");
}

GroundSunlight::~GroundSunlight() { release(); }

std::uint64_t GroundSunlight::bytesFor(std::uint32_t size) {
    std::uint64_t bytes = 0;
    for (std::uint32_t level = 0; level < levelsFor(size); ++level) {
        const std::uint64_t side = std::max(size >> level, 1u);
        bytes += side * side * 4;  // RGBA8
    }
    return bytes;
}

void GroundSunlight::release() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(context_.device, layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(context_.device, pool_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(context_.device, setLayout_, nullptr);
    if (sampler_) vkDestroySampler(context_.device, sampler_, nullptr);
    for (VkImageView view : levelViews_) vkDestroyImageView(context_.device, view, nullptr);
    if (view_) vkDestroyImageView(context_.device, view_, nullptr);
    if (image_) vkDestroyImage(context_.device, image_, nullptr);
    if (memory_) vkFreeMemory(context_.device, memory_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    pool_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
    sampler_ = VK_NULL_HANDLE;
    levelViews_.clear();
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

std::uint32_t GroundSunlight::firstLevel(VkExtent2D viewport) const {
    // A level with at least two texels a pixel along the viewport's longer side shows all a pixel can.
    const std::uint32_t side = std::max(viewport.width, viewport.height);
    std::uint32_t first = 0;
    while (first < kMostFirstLevel && first + 1 < levels_ && (size_ >> (first + 1)) >= 2 * side) ++first;
    return first;
}

void GroundSunlight::record(VkCommandBuffer cmd, const ShadowCascades& cascades, float depthBias, float texel,
                            std::uint32_t first) const {
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1};
    constexpr gpu::Access computeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    // The previous frame's ground must be done sampling before the levels are written again.
    gpu::imageBarrier(cmd, image_, all, {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0}, computeWrite,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
    first = std::min(first, static_cast<std::uint32_t>(sets_.size() - 1));
    const std::uint32_t side = std::max(size_ >> first, 1u);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[first], 0, nullptr);
    // One dispatch a cascade, over its square (the squares do not overlap: no barrier between them).
    for (std::uint32_t c = 0; c < cascades.count; ++c) {
        const VkRect2D square = cascades.texels(c, side);
        const Push push{cascades.clip[c], glm::vec4(0.0f, depthBias, texel, 0.0f), side,
                        std::min(kLevelsADispatch, levels_ - first), static_cast<float>(1u << first),
                        std::max(square.extent.width, 1u),
                        glm::uvec2(static_cast<std::uint32_t>(square.offset.x), static_cast<std::uint32_t>(square.offset.y))};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        const std::uint32_t blocks = (push.side + 15) / 16;
        vkCmdDispatch(cmd, blocks, blocks, 1);
    }
    gpu::imageBarrier(cmd, image_, all, computeWrite,
                      {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                      VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void GroundSunlight::recordAllLit(VkCommandBuffer cmd) const {
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1};
    constexpr gpu::Access clearWrite{VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    gpu::imageBarrier(cmd, image_, all, {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0}, clearWrite,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    const VkClearColorValue lit{{1.0f, 1.0f, 1.0f, 1.0f}};
    vkCmdClearColorImage(cmd, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &lit, 1, &all);
    gpu::imageBarrier(cmd, image_, all, clearWrite,
                      {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

}  // namespace render
