#pragma once
// One frame of the crowd, top to bottom in renderFrame: plan motion (CPU, only characters whose plan
// ran out) -> animate: on the CPU and upload bones, or on the GPU move every character -> cull and
// choose LODs -> (GPU path) bone matrices of the characters culling kept -> skin the visible (method)
// -> shadow map -> draw ground and characters -> resolve timestamps.
// Headless: it renders into an offscreen target; a presenter adds its commands through PresentHooks.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/gpu_timer.h"
#include "render/animation_pass.h"
#include "render/camera.h"
#include "render/character_draw.h"
#include "render/crowd_buffers.h"
#include "render/cull_pass.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/impostor_atlas.h"
#include "render/impostor_draw.h"
#include "render/render_target.h"
#include "render/shadow_map.h"
#include "render/scene_pass.h"
#include "skin/skinning_method.h"

namespace gpu { class VulkanContext; }

namespace frame {

struct RendererOptions {
    VkExtent2D size{1280, 720};
    skin::Method method = skin::Method::TwoPass;
    render::AnimationPath animation = render::AnimationPath::Gpu;
    render::CullSettings cull;
    bool shadows = true;                 // the directional light's shadow map, drawn from the same skinned vertices
    std::uint32_t shadowMapSize = 2048;  // texels per side
    std::uint32_t framesInFlight = 2;
    std::uint32_t maxTargetDimension = 0;  // 0: device limit
    gpu::PassClock passClock = gpu::PassClock::TimestampQueries;
    // With impostors on at construction (cull.impostors), the most characters drawn at a mesh level
    // (LOD 0-2) in a frame: skinned vertices, visible lists and draws are sized for it, and culling
    // demotes the characters beyond it to impostors. 0, or a crowd no larger: no cap.
    std::uint32_t meshCapacity = 0;
    render::ImpostorSettings impostorSettings;
    // An atlas baked before for the same models in the same order (tests, benchmarks): not baked again.
    std::shared_ptr<const render::ImpostorAtlas> atlas;
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
    void renderFrame(float time, const PresentHooks* hooks = nullptr);
    // Recreates the offscreen target at a new size (waits for the GPU).
    void resize(VkExtent2D size);
    // Switches the skinning method (waits for the GPU).
    void setMethod(skin::Method method);
    // Culling and LOD settings of the next frames (takes effect at once; the first switch to impostors
    // bakes the atlas, waiting for the GPU).
    void setCull(const render::CullSettings& cull);
    const render::CullSettings& cull() const { return cull_; }
    void setShadows(bool on) { shadows_ = on; }
    // Where the bone matrices come from, from the next frame on.
    void setAnimation(render::AnimationPath path) { animation_ = path; }
    render::AnimationPath animation() const { return animation_; }
    bool shadows() const { return shadows_; }
    // Hands over the statistics collected so far and starts a new list.
    std::vector<FrameStats> takeStats() { return std::exchange(stats_, {}); }
    // Waits for every frame in flight and collects its statistics.
    void finish();
    render::Rgba8Image readback();

    render::Camera camera;
    const std::vector<FrameStats>& stats() const { return stats_; }
    skin::SkinningMethod& method() { return *method_; }
    const render::GeometryPool& pool() const { return pool_; }
    const render::CrowdBuffers& buffers() const { return buffers_; }
    const render::DrawLists& drawLists() const { return lists_; }
    const render::CullPass& cullPass() const { return cullPass_; }
    // The impostor atlas, once impostors have been on (null before).
    std::shared_ptr<const render::ImpostorAtlas> impostorAtlas() const { return atlas_; }
    VkExtent2D extent() const { return target_->extent(); }
    // Where the crowd stands (measured once: it loops over every character).
    const render::CrowdShape& shape() const { return shape_; }
    // What the cull pass gets for the current camera and settings (the CPU reference takes the same).
    gpu::CullUniforms cullUniforms() const;
    // Device memory of the crowd's buffers, the method's resources and the render target.
    std::vector<skin::MemoryItem> memory() const;
    // The same per character of the crowd, by kind: "state" (record, motion segment, LOD state,
    // impostor-list entry, the vs baseline's draw slot), "bones" (its bone block), "mesh slots" (visible
    // lists, draws and the method's skinned vertices, sized for the mesh-level capacity), "atlas" (the
    // impostor atlas shared by all), "fixed" (geometry, clip library, render target, shadow map).
    std::map<std::string, double> memoryPerCharacter() const;

private:
    struct Frame {
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        bool pending = false;
        FrameStats stats;
    };
    void collect(Frame& frame, std::uint32_t slot);
    void recordFrame(VkCommandBuffer cmd, std::uint32_t slot, float time, render::AnimationPath path,
                     const PresentHooks* hooks);
    // The path this frame takes: none when the method no longer reads bones; the CPU for the fixed
    // layout's one frame (it needs every character's bones, not only the visible ones).
    std::optional<render::AnimationPath> animationThisFrame() const;
    void enableImpostors();
    void recordCulling(VkCommandBuffer cmd, std::uint32_t slot);
    void recordShadows(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& lightViewProjection);
    void recordScene(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& lightViewProjection);
    glm::mat4 lightViewProjection() const;
    void submit(Frame& frame, const PresentHooks* hooks);
    std::unique_ptr<skin::SkinningMethod> createMethod(skin::Method method) const;

    const gpu::VulkanContext& context_;
    crowd::Crowd& crowd_;
    render::GeometryPool pool_;
    render::CrowdBuffers buffers_;
    render::DrawLists lists_;
    render::CullPass cullPass_;
    render::AnimationPass animationPass_;
    std::unique_ptr<render::RenderTarget> target_;
    std::uint32_t maxTargetDimension_;
    render::CrowdShape shape_;
    render::ShadowMap shadowMap_;
    render::ScenePass scene_;
    render::CharacterDraw draw_;
    gpu::GpuTimer timer_;
    std::unique_ptr<skin::SkinningMethod> method_;
    render::ImpostorSettings impostorSettings_;
    std::shared_ptr<const render::ImpostorAtlas> atlas_;
    std::unique_ptr<render::ImpostorDraw> impostorDraw_;
    render::CullSettings cull_;
    render::AnimationPath animation_;
    bool shadows_;
    bool shadowMapReady_ = false;  // in the layout the shading samples (rendered or cleared once)
    std::vector<Frame> frames_;
    std::vector<FrameStats> stats_;
    std::uint64_t frameIndex_ = 0;
    double lastFrameStart_ = -1.0;
};

}  // namespace frame
