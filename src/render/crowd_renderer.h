#pragma once
// One frame of the crowd, top to bottom: animate on the CPU -> upload bones -> skin (method) ->
// draw ground and characters -> resolve timestamps. Headless: it renders into an offscreen target.
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/gpu_timer.h"
#include "render/camera.h"
#include "render/crowd_buffers.h"
#include "render/material_texture.h"
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
    gpu::PassClock passClock = gpu::PassClock::TimestampQueries;
};

struct FrameStats {
    double animateMs = 0.0;  // CPU: sampling clips and computing bone matrices
    double recordMs = 0.0;   // CPU: recording and submitting the command buffer
    double intervalMs = 0.0; // wall clock since the previous frame started (0 for the first)
    std::vector<gpu::PassTime> gpu;  // per pass, from timestamp queries
};

// What a presenter (the windowed viewer) adds to a frame: semaphores of its swapchain and commands
// recorded after the scene, e.g. a blit of the scene image to the swapchain image and the UI.
struct PresentHooks {
    VkSemaphore waitSemaphore = VK_NULL_HANDLE;    // waited before the scene is written
    VkSemaphore signalSemaphore = VK_NULL_HANDLE;  // signalled when the frame's commands are done
    // The scene colour image is in VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, its writes visible to transfers.
    std::function<void(VkCommandBuffer cmd, VkImage sceneColor, VkExtent2D extent)> recordAfterScene;
};

class CrowdRenderer {
public:
    CrowdRenderer(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RendererOptions& options);
    ~CrowdRenderer();
    CrowdRenderer(const CrowdRenderer&) = delete;
    CrowdRenderer& operator=(const CrowdRenderer&) = delete;

    // Renders the crowd at animation time `time` seconds.
    void renderFrame(float time, const PresentHooks* hooks = nullptr);
    // Recreates the offscreen target at a new size (waits for the GPU).
    void resize(VkExtent2D size);
    // Switches the skinning method (waits for the GPU).
    void setMethod(skin::Method method);
    // Hands over the statistics collected so far and starts a new list.
    std::vector<FrameStats> takeStats() { return std::exchange(stats_, {}); }
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
    void recordFrame(VkCommandBuffer cmd, std::uint32_t slot, bool uploadBones, const PresentHooks* hooks);
    void submit(Frame& frame, const PresentHooks* hooks);

    const gpu::VulkanContext& context_;
    const crowd::Crowd& crowd_;
    CrowdBuffers buffers_;
    std::unique_ptr<RenderTarget> target_;
    std::uint32_t maxTargetDimension_;
    MaterialTexture material_;
    ScenePass scene_;
    gpu::GpuTimer timer_;
    std::unique_ptr<skin::SkinningMethod> method_;
    std::vector<Frame> frames_;
    std::vector<FrameStats> stats_;
    std::uint64_t frameIndex_ = 0;
    double lastFrameStart_ = -1.0;
};

}  // namespace render
