#pragma once
// What the programs share: building the model and crowd from options, checking the crowd fits the
// device, and running the headless render loop.
#include <string>
#include <vector>

#include "app/options.h"
#include "crowd/crowd.h"
#include "model/skinned_model.h"
#include "render/crowd_renderer.h"
#include "skin/cpu_skinning.h"

namespace gpu { class VulkanContext; }

namespace app {

// "soldier", "horse", or a glTF 2.0 file: a name ending in .gltf or .glb, or any existing file.
// Throws gpu::Error for anything else and for a file that cannot be loaded. Notes on what a glTF
// file had that the character leaves out are appended to `notes` when given. A glTF file's external
// files must lie inside `assetRoot` (--asset-root), or its own folder when empty.
model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes = nullptr,
                              const std::string& assetRoot = {});

// The clip `clip` names (by name, or by index), or the crowd's default clip when `clip` is empty.
// Throws gpu::Error listing the model's clips.
std::uint32_t clipIndex(const model::SkinnedModel& model, const std::string& clip);

// One character's skinned vertices at `time` seconds into `clip`, standing at the origin (character
// transform = identity): the model's own space, which for glTF is its scene's world space. A clip
// index past the last gives the rest pose. CPU jobs only: sample, local to model (with the
// skeleton's root transform), skinning matrices, skin.
std::vector<skin::CpuSkinnedVertex> poseOnCpu(const model::SkinnedModel& model, std::uint32_t clip, float time);

// The crowd's characters for the scene options (grid layout, clip by name or index, or random).
std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const SceneOptions& scene);

// Throws a one-line gpu::Error when the crowd cannot fit in the device's memory for this method.
void checkCrowdFits(const gpu::VulkanContext& context, const model::SkinnedModel& model, std::uint32_t count,
                    skin::Method method, VkExtent2D size);

// Animation time of frame `index`: a fixed 60 Hz step, so runs are reproducible.
inline float frameTime(std::uint32_t index) { return static_cast<float>(index) / 60.0f; }

}  // namespace app
