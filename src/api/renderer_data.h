#pragma once
// The renderer behind crowdgpu::Renderer: a borrowed-device context and the record-only frame.
#include <memory>

#include "crowdgpu/renderer.hpp"
#include "frame/crowd_recorder.h"
#include "gpu/vulkan_context.h"
#include "render/edge_filter.h"

namespace crowdgpu::detail {

struct RendererData {
    std::shared_ptr<gpu::VulkanContext> context;  // wraps the host's device; owns nothing of it
    RendererSettings settings;
    std::unique_ptr<frame::CrowdRecorder> frame;
    std::unique_ptr<render::EdgeFilter> edgeFilter;  // with settings.edgeFilter
    std::vector<Model> models;  // the crowd's models, which the frame's layout points into, kept alive
};

// A renderer with every internal option (a shared impostor atlas, a smaller target limit): the
// programs' frame driver and the tests. The public constructor goes through the same checks.
Renderer makeRenderer(const Device& device, const crowd::Crowd& crowd, const frame::RecorderOptions& options,
                      const RendererSettings& settings);

// The internal options for public settings.
frame::RecorderOptions rendererOptions(const RendererSettings& settings);
skin::Method internalMethod(Method method);

}  // namespace crowdgpu::detail
