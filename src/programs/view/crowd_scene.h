#pragma once
// The crowd the viewer shows: model, characters and renderer, as crowd-render builds them from the
// same options, rebuilt when the panel changes the model or the crowd's size.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/crowd_app.h"
#include "app/options.h"
#include "app/crowd_renderer.h"
#include "app/world.h"

namespace app { class HostDevice; }

namespace view {

class CrowdScene {
public:
    // Throws app::Error (one line) for a model, clip or crowd size that cannot be shown.
    // `meshCapacity`: --mesh-capacity, which applies (as in crowd-render) when impostors are on;
    // `antiAliasing`: --aa.
    CrowdScene(const app::HostDevice& context, const app::SceneOptions& scene, crowdgpu::Method method,
               const app::CullOptions& cull, bool shadows, std::uint32_t meshCapacity, app::AntiAliasing antiAliasing,
               VkExtent2D size);

    // Builds the crowd for new scene options. Checks everything that can be checked (model, clip,
    // memory) before the current crowd is released, and throws app::Error keeping it when a check
    // fails. A clip the new model lacks falls back to its default clip, with a note.
    void rebuild(app::SceneOptions scene, VkExtent2D size);
    // Switches the skinning method; throws app::Error, keeping the current one, when the crowd
    // would not fit in device memory with it.
    void setMethod(crowdgpu::Method method, VkExtent2D size);
    // Shadows on or off, now and for crowds rebuilt later.
    void setShadows(bool on) { shadows_ = on, renderer_->setShadows(on); }
    // Where bone matrices come from (--animation), now and for crowds rebuilt later. The CPU path keeps a
    // bone block per character: a crowd whose blocks do not fit is refused (app::Error) and nothing changes.
    void setAnimation(crowdgpu::Animation path, VkExtent2D size);

    app::CrowdRenderer& renderer() { return *renderer_; }
    const app::CrowdRenderer& renderer() const { return *renderer_; }
    const crowdgpu::Crowd& crowd() const { return world_->crowd; }
    // A replayed recording's duration (--trajectories), seconds; 0 without one.
    double recordingDuration() const { return world_->recording ? world_->recording->info.duration() : 0.0; }
    // The crowd's first model (the only one unless --model lists several).
    const crowdgpu::Model& model() const { return models_.models.front(); }
    const app::SceneOptions& options() const { return scene_; }
    crowdgpu::Method method() const { return method_; }
    // The largest crowd of this model that fits the device's memory and storage-buffer range with this
    // method (the panel's limit).
    std::uint32_t maxCharacters(VkExtent2D size) const;
    // The size to draw a window of `window` pixels at with the current settings: the window's own, or,
    // past the device's memory or image limits (a huge window with multisampling), the largest of its
    // shape that fits (app::largestFittingSize), with why.
    app::FittingSize fittingSize(VkExtent2D window) const;
    // What loading the model or resolving the clip noted (glTF parts left out, a clip replaced).
    std::vector<std::string> takeNotes() { return std::exchange(notes_, {}); }

private:
    app::RendererOptions rendererOptions(crowdgpu::Method method, VkExtent2D size) const;

    const app::HostDevice& context_;
    app::SceneOptions scene_;
    crowdgpu::Method method_;
    app::CullOptions cull_;
    bool shadows_;
    std::uint32_t meshCapacity_;
    app::AntiAliasing antiAliasing_;
    crowdgpu::Animation animation_ = crowdgpu::Animation::Gpu;
    app::CrowdModels models_;
    std::unique_ptr<app::World> world_;  // the crowd, its ground and what drives it (app/world.h)
    std::unique_ptr<app::CrowdRenderer> renderer_;
    std::vector<std::string> notes_;
};

// The panel's culling settings of a renderer's.
app::CullOptions cullOf(const crowdgpu::RendererSettings& settings);

}  // namespace view
