#pragma once
// The programs' frame driver: the reference embedding of the library. It owns what a host owns — the
// device (app::HostDevice), command buffers, fences, the offscreen target, the pass timer and the
// statistics — and draws each frame through crowdgpu::Renderer's public record calls:
// plan (Crowd::advanceTo) -> recordCompute -> recordShadows -> begin the target's pass -> recordCharacters
// (with the ground behind them: RendererSettings::ground) -> end -> [recordEdgeFilter] -> submit. A presenter (the viewer)
// adds its commands through PresentHooks.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include <crowdgpu/crowd.hpp>
#include <crowdgpu/renderer.hpp>

#include "app/camera.h"
#include "app/crowd_driver.h"
#include "app/gpu_timer.h"
#include "app/render_target.h"

namespace app {

class HostDevice;

// The library's settings, and what the driver owns: the target's size and the pass clock.
struct RendererOptions : crowdgpu::RendererSettings {
    VkExtent2D size{1280, 720};
    PassClock passClock = PassClock::TimestampQueries;
};

struct FrameStats {
    double driveMs = 0.0;    // CPU: the world's driver (its own work and its calls: app::CrowdDriver::update)
    double ingestMs = 0.0;   // of that, its calls into the crowd (spawns, removals, samples handed over)
    double planMs = 0.0;     // CPU: planning the motion segments whose plan ran out (Crowd::advanceTo)
    double animateMs = 0.0;  // CPU path: sampling clips and computing bone matrices (0 on the GPU path)
    double recordMs = 0.0;   // CPU: culling on the CPU (--cull cpu), recording and submitting
    double intervalMs = 0.0; // wall clock since the previous frame started (0 for the first)
    double sceneSeconds = 0.0;  // the animation time the frame was rendered at (renderFrame's `time`)
    std::vector<PassTime> gpu;  // per pass, from timestamp queries
    crowdgpu::FrameCounts lods{};  // visible characters and triangles drawn per level of detail
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
    // The crowd is planned (advanceTo) by each frame, so it must outlive the renderer and not be shared
    // with another one.
    CrowdRenderer(const HostDevice& device, crowdgpu::Crowd& crowd, const RendererOptions& options);
    // Around a library renderer made elsewhere (the library's tests make one with internal options).
    CrowdRenderer(const HostDevice& device, crowdgpu::Crowd& crowd, crowdgpu::Renderer renderer, VkExtent2D size,
                  PassClock passClock = PassClock::TimestampQueries);
    ~CrowdRenderer();
    CrowdRenderer(const CrowdRenderer&) = delete;
    CrowdRenderer& operator=(const CrowdRenderer&) = delete;

    // Renders the crowd at animation time `time` seconds, seen by `camera`.
    void renderFrame(double time, const PresentHooks* hooks = nullptr);
    // What moves the crowd besides its behaviour each frame (app/crowd_driver.h; null: nothing). It must
    // outlive the renderer's frames.
    void setDriver(CrowdDriver* driver) { driver_ = driver; }
    // Recreates the offscreen target at a new size (waits for the GPU).
    void resize(VkExtent2D size);
    // Switches the skinning method (waits for the GPU).
    void setMethod(crowdgpu::Method method);
    // Culling, LOD and impostor settings of the next frames (the first switch to impostors bakes the
    // atlas, waiting for the GPU).
    void setCulling(crowdgpu::Culling culling, bool lod, bool impostors);
    void setLevels(const float lodThresholds[2], float hysteresis, float impostorThreshold) {
        renderer_.setLevels(lodThresholds, hysteresis, impostorThreshold);
    }
    void setShadows(bool on) { renderer_.setShadows(on); }
    void setAnimation(crowdgpu::Animation animation) { renderer_.setAnimation(animation); }
    const crowdgpu::RendererSettings& settings() const { return renderer_.settings(); }
    // Hands over the statistics collected so far and starts a new list.
    std::vector<FrameStats> takeStats() { return std::exchange(stats_, {}); }
    // Waits for every frame in flight and collects its statistics.
    void finish();
    Rgba8Image readback();

    Camera camera;
    const std::vector<FrameStats>& stats() const { return stats_; }
    // Wall-clock milliseconds of the setup submissions so far (uploads and the impostor bake).
    double setupMs() const { return setupMs_; }
    VkExtent2D extent() const { return target_->extent(); }
    // Device memory of the library's resources and the render target.
    std::vector<crowdgpu::MemoryItem> memory() const;
    // The library's per-character figures, the render target counted as fixed.
    std::map<std::string, double> memoryPerCharacter() const;
    // The library's handle, for what a host would call directly.
    crowdgpu::Renderer& library() { return renderer_; }
    const crowdgpu::Renderer& library() const { return renderer_; }

private:
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
        FrameStats stats;
    };
    void runSetup();
    void collect(Frame& frame, std::uint32_t slot);
    void recordFrame(VkCommandBuffer cmd, std::uint32_t slot, double time, const PresentHooks* hooks);
    void submit(Frame& frame, const PresentHooks* hooks);
    void waitIdle();

    const HostDevice& device_;
    crowdgpu::Crowd& crowd_;
    CrowdDriver* driver_ = nullptr;
    crowdgpu::Renderer renderer_;
    std::unique_ptr<RenderTarget> target_;
    GpuTimer timer_;
    std::vector<Frame> frames_;
    std::vector<FrameStats> stats_;
    std::uint64_t frameIndex_ = 0;
    double lastFrameStart_ = -1.0;
    double setupMs_ = 0.0;
};

}  // namespace app
