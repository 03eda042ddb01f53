#include "render/visibility_resolve.h"

#include "gpu/pipeline.h"
#include "impostor_resolve.vert.spv.h"

namespace render {

VkPipeline createVisibilityResolve(const gpu::VulkanContext& context, std::span<const std::uint32_t> fragmentShader,
                                   VkPipelineLayout layout, const TargetFormat& target) {
    gpu::GraphicsPipelineDesc desc;
    desc.vertexShader = impostor_resolve_vert_spv;  // one triangle over the viewport
    desc.fragmentShader = fragmentShader;
    desc.colorFormats = {target.color};
    desc.depthFormat = target.depth;
    desc.layout = layout;
    desc.cullMode = VK_CULL_MODE_NONE;
    return gpu::createGraphicsPipeline(context, desc);
}

}  // namespace render
