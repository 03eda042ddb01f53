#pragma once
// The programs' frame driver: the reference embedding of the library. It owns what a host owns — the
// device (the programs' VulkanContext), command buffers, fences, the offscreen target, the pass
// timer and the statistics — and draws each frame through crowdgpu::Renderer's public record calls:
// plan (Crowd::advanceTo) -> recordCompute -> recordShadows -> begin the target's pass -> recordGround
// -> recordCharacters -> end -> submit. A presenter (the viewer) adds its commands through PresentHooks.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowdgpu/renderer.hpp"
#include "frame/crowd_recorder.h"
#include "gpu/gpu_timer.h"
#include "render/camera.h"
#include "render/render_target.h"

namespace gpu { class VulkanContext; }

namespace app {

// The library's options, and what the driver owns: the target's size and the pass clock.
struct RendererOptions : frame::RecorderOptions {
    VkExtent2D size{1280, 720};
    gpu::PassClock passClock = gpu::PassClock::TimestampQueries;
};

struct FrameStats {
    double planMs = 0.0;     // CPU: planning the motion segments whose plan ran out (crowd::Crowd::advanceTo)
    double animateMs = 0.0;  // CPU path: sampling clips and computing bone matrices (0 on the GPU path)
    double recordMs = 0.0;   // CPU: culling on the CPU (--cull cpu), recording and submitting
    double intervalMs = 0.0; // wall clock since the previous frame started (0 for the first)
    std::vector<gpu::PassTime> gpu;  // per pass, from timestamp queries
    render::LodCounts lods;  // visible characters and triangles drawn per level of detail
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
    CrowdRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd, const RendererOptions& options);
    ~CrowdRenderer();
    CrowdRenderer(const CrowdRenderer&) = delete;
    CrowdRenderer& operator=(const CrowdRenderer&) = delete;

    // Renders the crowd at animation time `time` seconds, seen by `camera`.
    void renderFrame(double time, const PresentHooks* hooks = nullptr);
    // Recreates the offscreen target at a new size (waits for the GPU).
    void resize(VkExtent2D size);
    // Switches the skinning method (waits for the GPU).
    void setMethod(skin::Method method);
    // Culling and LOD settings of the next frames (the first switch to impostors bakes the atlas,
    // waiting for the GPU).
    void setCull(const render::CullSettings& cull);
    const render::CullSettings& cull() const { return recorder().cull(); }
    void setShadows(bool on) { recorder().setShadows(on); }
    bool shadows() const { return recorder().shadows(); }
    void setAnimation(render::AnimationPath path) { recorder().setAnimation(path); }
    render::AnimationPath animation() const { return recorder().animation(); }
    // Hands over the statistics collected so far and starts a new list.
    std::vector<FrameStats> takeStats() { return std::exchange(stats_, {}); }
    // Waits for every frame in flight and collects its statistics.
    void finish();
    render::Rgba8Image readback();

    render::Camera camera;
    const std::vector<FrameStats>& stats() const { return stats_; }
    skin::SkinningMethod& method() { return recorder().method(); }
    const render::GeometryPool& pool() const { return recorder().pool(); }
    const render::CrowdBuffers& buffers() const { return recorder().buffers(); }
    const render::DrawLists& drawLists() const { return recorder().drawLists(); }
    const render::CullPass& cullPass() const { return recorder().cullPass(); }
    std::shared_ptr<const render::ImpostorAtlas> impostorAtlas() const { return recorder().impostorAtlas(); }
    // Wall-clock milliseconds of the setup submissions so far (uploads and the impostor bake).
    double setupMs() const { return setupMs_; }
    VkExtent2D extent() const { return target_->extent(); }
    const render::CrowdShape& shape() const { return recorder().shape(); }
    // What the cull pass gets for the current camera and settings (the CPU reference takes the same).
    gpu::CullUniforms cullUniforms() const { return recorder().cullUniforms(view(0.0)); }
    // Device memory of the library's resources and the render target.
    std::vector<skin::MemoryItem> memory() const;
    // The library's per-character figures, the render target counted as fixed.
    std::map<std::string, double> memoryPerCharacter() const;
    // The library's handle, for what a host would call directly.
    crowdgpu::Renderer& library() { return renderer_; }

private:
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
        FrameStats stats;
    };
    frame::CrowdRecorder& recorder() const;
    render::FrameView view(double time) const;
    void runSetup();
    void collect(Frame& frame, std::uint32_t slot);
    void recordFrame(VkCommandBuffer cmd, std::uint32_t slot, double time, const PresentHooks* hooks);
    void submit(Frame& frame, const PresentHooks* hooks);
    void waitIdle();

    const gpu::VulkanContext& context_;
    crowd::Crowd& crowd_;
    crowdgpu::Renderer renderer_;
    std::unique_ptr<render::RenderTarget> target_;
    gpu::GpuTimer timer_;
    std::vector<Frame> frames_;
    std::vector<FrameStats> stats_;
    std::uint64_t frameIndex_ = 0;
    double lastFrameStart_ = -1.0;
    double setupMs_ = 0.0;
};

}  // namespace app
