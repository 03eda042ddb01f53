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
#include "crowd/crowd.h"
#include "model/skinned_model.h"
#include "app/crowd_renderer.h"

namespace gpu { class VulkanContext; }

namespace view {

class CrowdScene {
public:
    // Throws gpu::Error (one line) for a model, clip or crowd size that cannot be shown.
    // `meshCapacity`: --mesh-capacity, which applies (as in crowd-render) when impostors are on.
    CrowdScene(const gpu::VulkanContext& context, const app::SceneOptions& scene, skin::Method method,
               const render::CullSettings& cull, bool shadows, std::uint32_t meshCapacity, VkExtent2D size);

    // Builds the crowd for new scene options. Checks everything that can be checked (model, clip,
    // memory) before the current crowd is released, and throws gpu::Error keeping it when a check
    // fails. A clip the new model lacks falls back to its default clip, with a note.
    void rebuild(app::SceneOptions scene, VkExtent2D size);
    // Switches the skinning method; throws gpu::Error, keeping the current one, when the crowd
    // would not fit in device memory with it.
    void setMethod(skin::Method method, VkExtent2D size);
    // Shadows on or off, now and for crowds rebuilt later.
    void setShadows(bool on) { shadows_ = on, renderer_->setShadows(on); }
    // Where bone matrices come from (--animation), now and for crowds rebuilt later.
    void setAnimation(render::AnimationPath path) { animation_ = path, renderer_->setAnimation(path); }

    app::CrowdRenderer& renderer() { return *renderer_; }
    const app::CrowdRenderer& renderer() const { return *renderer_; }
    const crowd::Crowd& crowd() const { return *crowd_; }
    // The crowd's first model (the only one unless --model lists several).
    const model::SkinnedModel& model() const { return *models_.models.front(); }
    const app::SceneOptions& options() const { return scene_; }
    skin::Method method() const { return method_; }
    // The largest crowd of this model that fits the device's memory and storage-buffer range with this
    // method (the panel's limit).
    std::uint32_t maxCharacters(VkExtent2D size) const;
    // What loading the model or resolving the clip noted (glTF parts left out, a clip replaced).
    std::vector<std::string> takeNotes() { return std::exchange(notes_, {}); }

private:
    // The mesh-level cap of a crowd built with these cull settings (0: none).
    std::uint32_t meshCapacityFor(const render::CullSettings& cull) const { return cull.impostors ? meshCapacity_ : 0u; }

    const gpu::VulkanContext& context_;
    app::SceneOptions scene_;
    skin::Method method_;
    render::CullSettings cull_;
    bool shadows_;
    std::uint32_t meshCapacity_;
    render::AnimationPath animation_ = render::AnimationPath::Gpu;
    app::CrowdModels models_;
    std::unique_ptr<crowd::Crowd> crowd_;
    std::unique_ptr<app::CrowdRenderer> renderer_;
    std::vector<std::string> notes_;
};

}  // namespace view
