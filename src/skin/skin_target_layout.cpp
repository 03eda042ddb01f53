#include "skin/skin_target_layout.h"

#include <algorithm>

#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace skin {

std::uint32_t SkinTargetLayout::charactersInTile(std::uint32_t tile) const {
    return std::min(charactersPerTile, characterCount - firstCharacter(tile));
}

VkExtent2D SkinTargetLayout::tileExtent(std::uint32_t tile) const {
    return {width, charactersInTile(tile) * rowsPerCharacter};
}

SkinTargetLayout planSkinTargets(std::uint32_t vertexCount, std::uint32_t characterCount, std::uint32_t maxDimension) {
    if (vertexCount == 0 || characterCount == 0 || maxDimension == 0)
        throw gpu::Error("skinning target: vertex count, character count and image size must be positive");
    SkinTargetLayout layout;
    layout.vertexCount = vertexCount;
    layout.characterCount = characterCount;
    layout.width = std::min(vertexCount, maxDimension);
    layout.rowsPerCharacter = (vertexCount + layout.width - 1) / layout.width;
    if (layout.rowsPerCharacter > maxDimension)
        throw gpu::Error("model has " + std::to_string(vertexCount) + " vertices, more than one " +
                         std::to_string(maxDimension) + "-texel-square skinning target holds");
    layout.charactersPerTile = std::min(characterCount, maxDimension / layout.rowsPerCharacter);
    layout.tileCount = (characterCount + layout.charactersPerTile - 1) / layout.charactersPerTile;
    return layout;
}

gpu::SkinPassParams skinPassParams(const SkinTargetLayout& layout, std::uint32_t tile, std::uint32_t boneStride) {
    gpu::SkinPassParams params{};
    params.counts = {layout.charactersInTile(tile), layout.vertexCount, layout.rowsPerCharacter,
                     layout.firstCharacter(tile)};
    params.strides = {layout.width, boneStride, 0, 0};
    return params;
}

std::uint32_t maxSkinTargetDimension(const gpu::VulkanContext& context, std::uint32_t requested) {
    const VkPhysicalDeviceLimits& limits = context.properties.limits;
    const std::uint32_t device =
        std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxFramebufferHeight});
    return requested ? std::min(requested, device) : device;
}

}  // namespace skin
