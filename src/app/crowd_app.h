#pragma once
// What the programs share: building the model and crowd from options, checking the crowd fits the
// device, and running the headless render loop.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/options.h"
#include "crowd/crowd.h"
#include "model/skinned_model.h"
#include "app/crowd_renderer.h"
#include "render/camera_path.h"
#include "skin/cpu_skinning.h"

namespace gpu { class VulkanContext; }

namespace app {

// "soldier", "horse", or a glTF 2.0 file: a name ending in .gltf or .glb, or any existing file.
// Throws gpu::Error for anything else and for a file that cannot be loaded. Notes on what a glTF
// file had that the character leaves out are appended to `notes` when given. A glTF file's external
// files must lie inside `assetRoot` (--asset-root), or its own folder when empty. The model comes with
// its levels of detail (model::buildLods, which reorders its vertices) and its pose sphere.
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

// --model's list: NAME[:WEIGHT],... with positive weights (1 when left out). Throws gpu::Error.
std::vector<std::pair<std::string, float>> parseModelList(const std::string& list);

// The models of a crowd and each one's share of it.
struct CrowdModels {
    std::vector<std::unique_ptr<model::SkinnedModel>> models;
    std::vector<float> weights;
    std::vector<const model::SkinnedModel*> pointers() const;
};
// "soldier+horse": the models' own names, for reports.
std::string modelNames(const CrowdModels& models);
CrowdModels loadModels(const std::string& list, std::uint32_t seed, std::vector<std::string>* notes = nullptr,
                       const std::string& assetRoot = {});

// The crowd's characters for the scene options (grid layout, models by weight, clip by name or index,
// or random). In a crowd of several models, a named clip a model lacks leaves it its default clip, and
// models far from human size (under 0.1 or over 10 units tall, as some glTF files are) are scaled to
// 1.8 units so that they stand together.
std::vector<crowd::Character> buildCharacters(const CrowdModels& models, const SceneOptions& scene);
std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const SceneOptions& scene);
// The crowd of the scene options: those characters doing the scene's behaviour (seeded by its seed).
// Living crowds (march, mill) also vary each character's scale by up to 8 % and its colour a little.
crowd::Crowd buildCrowd(const CrowdModels& models, const SceneOptions& scene);

// Device memory the crowd needs with this method and image size (the sizes the allocations will have).
// `meshCapacity` > 0: impostors are on and at most that many characters are drawn at a mesh level
// (their skinned vertices and lists are sized for it; the impostor atlas is counted too).
std::uint64_t estimateCrowdBytes(const gpu::VulkanContext& context, const crowd::Crowd& crowd, skin::Method method,
                                 VkExtent2D size, std::uint32_t meshCapacity = 0);
// Throws a one-line gpu::Error when the crowd cannot fit in the device's memory for this method, or a
// buffer it binds whole as a storage buffer is over the device's range (skin/storage_ranges.h).
void checkCrowdFits(const gpu::VulkanContext& context, const crowd::Crowd& crowd, skin::Method method, VkExtent2D size,
                    std::uint32_t meshCapacity = 0);

// Where the crowd stands, for camera paths.
render::CrowdShape crowdShape(const crowd::Crowd& crowd);

// Animation time of frame `index`: a fixed 60 Hz step from `start` seconds, so runs are reproducible.
inline double frameTime(std::uint32_t index, double start = 0.0) { return start + static_cast<double>(index) / 60.0; }

}  // namespace app
