#pragma once
// One frame of the crowd, top to bottom: animate on the CPU -> upload bones -> skin (method) ->
// draw ground and characters -> resolve timestamps. Headless: it renders into an offscreen target.
#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/gpu_timer.h"
#include "render/camera.h"
#include "render/crowd_buffers.h"
#include "render/render_target.h"
#include "render/scene_pass.h"
#include "skin/skinning_method.h"

namespace gpu { class VulkanContext; }

namespace render {

struct RendererOptions {
    VkExtent2D size{1280, 720};
    skin::Method method = skin::Method::TwoPass;
    std::uint32_t framesInFlight = 2;
    std::uint32_t maxTargetDimension = 0;  // 0: device limit
};

struct FrameStats {
    double animateMs = 0.0;  // CPU: sampling clips and computing bone matrices
    double recordMs = 0.0;   // CPU: recording and submitting the command buffer
    double intervalMs = 0.0; // wall clock since the previous frame started (0 for the first)
    std::vector<gpu::PassTime> gpu;  // per pass, from timestamp queries
};

class CrowdRenderer {
public:
    CrowdRenderer(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RendererOptions& options);
    ~CrowdRenderer();
    CrowdRenderer(const CrowdRenderer&) = delete;
    CrowdRenderer& operator=(const CrowdRenderer&) = delete;

    // Renders the crowd at animation time `time` seconds.
    void renderFrame(float time);
    // Waits for every frame in flight and collects its statistics.
    void finish();
    Rgba8Image readback();

    Camera camera;
    const std::vector<FrameStats>& stats() const { return stats_; }
    skin::SkinningMethod& method() { return *method_; }
    const CrowdBuffers& buffers() const { return buffers_; }
    // Device memory of the crowd buffers, the method's resources and the render target.
    std::vector<skin::MemoryItem> memory() const;

private:
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
        FrameStats stats;
    };
    void collect(Frame& frame, std::uint32_t slot);
    void recordFrame(VkCommandBuffer cmd, std::uint32_t slot);

    const gpu::VulkanContext& context_;
    const crowd::Crowd& crowd_;
    CrowdBuffers buffers_;
    RenderTarget target_;
    ScenePass scene_;
    gpu::GpuTimer timer_;
    std::unique_ptr<skin::SkinningMethod> method_;
    std::vector<Frame> frames_;
    std::vector<FrameStats> stats_;
    std::uint64_t frameIndex_ = 0;
    double lastFrameStart_ = -1.0;
};

}  // namespace render
