#include "render/visibility_resolve.h"

#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "impostor_resolve.vert.spv.h"
#include "visibility_tiles.vert.spv.h"

namespace render {

std::uint64_t visibilityBytes(VkExtent2D extent) { return std::uint64_t{extent.width} * extent.height * 8; }

bool visibilityFits(const VkPhysicalDeviceLimits& limits, VkExtent2D extent) {
    return visibilityBytes(extent) <= limits.maxStorageBufferRange;
}

VisibilityResolve::VisibilityResolve(const gpu::VulkanContext& context, std::span<const std::uint32_t> fragmentShader,
                                     VkPipelineLayout layout, const TargetFormat& target, std::uint32_t framesInFlight,
                                     std::uint32_t tilePixels, ResolveWrite write)
    : context_(context) {
    if (tilePixels > 0) tiles_ = std::make_unique<VisibilityTiles>(context, framesInFlight, tilePixels);
    gpu::GraphicsPipelineDesc desc;
    desc.fragmentShader = fragmentShader;
    desc.colorFormats = {target.color};
    desc.depthFormat = target.depth;
    desc.samples = target.samples;  // a covered pixel's colour and depth go to all its samples
    desc.layout = layout;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.blendOver = write == ResolveWrite::LayerOver;
    desc.depthWrite = write == ResolveWrite::Opaque;
    if (tiles_) {
        // An instance per listed tile, its place in the list's tiles as the instance's attribute.
        desc.vertexShader = visibility_tiles_vert_spv;
        desc.bindings = {{0, sizeof(std::uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
        desc.attributes = {{0, 0, VK_FORMAT_R32_UINT, 0}};
        desc.vertexConstants = {tilePixels};
    } else {
        desc.vertexShader = impostor_resolve_vert_spv;  // one triangle over the viewport
    }
    pipeline_ = gpu::createGraphicsPipeline(context, desc);
}

VisibilityResolve::~VisibilityResolve() {
    if (pipeline_) vkDestroyPipeline(context_.device, pipeline_, nullptr);
}

void VisibilityResolve::recordTiles(VkCommandBuffer cmd, std::uint32_t slot, const gpu::Buffer& visibility,
                                    VkExtent2D extent) {
    if (tiles_) tiles_->record(cmd, slot, visibility, extent);
}

void VisibilityResolve::bind(VkCommandBuffer cmd) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
}

void VisibilityResolve::draw(VkCommandBuffer cmd, std::uint32_t slot) const {
    if (tiles_)
        tiles_->recordDraw(cmd, slot);
    else
        vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace render
