#pragma once
// What the programs share: building the model and crowd from options, checking the crowd fits the
// device, and running the headless render loop.
#include <string>
#include <vector>

#include "app/options.h"
#include "crowd/crowd.h"
#include "model/skinned_model.h"
#include "render/crowd_renderer.h"

namespace gpu { class VulkanContext; }

namespace app {

// "soldier" or "horse". Throws gpu::Error for anything else.
model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed);

// The crowd's characters for the scene options (grid layout, clip by name or index, or random).
std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const SceneOptions& scene);

// Throws a one-line gpu::Error when the crowd cannot fit in the device's memory for this method.
void checkCrowdFits(const gpu::VulkanContext& context, const model::SkinnedModel& model, std::uint32_t count,
                    skin::Method method, VkExtent2D size);

// Animation time of frame `index`: a fixed 60 Hz step, so runs are reproducible.
inline float frameTime(std::uint32_t index) { return static_cast<float>(index) / 60.0f; }

}  // namespace app
