#pragma once
// What the programs share: building the models and crowd from options with the library's public
// API, and checking the crowd fits the device before a renderer is made.
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include <crowdgpu/crowd.hpp>
#include <crowdgpu/model.hpp>
#include <crowdgpu/renderer.hpp>

#include "app/options.h"

namespace app {

class HostDevice;

// "soldier", "horse", or a glTF 2.0 file: a name ending in .gltf or .glb, or any existing file.
// Throws Error for anything else and for a file that cannot be loaded. Notes on what a glTF file had
// that the character leaves out are appended to `notes` when given. A glTF file's external files
// must lie inside `assetRoot` (--asset-root), or its own folder when empty.
// `props` false: the built-in soldier without its props (--props off: what they cost).
crowdgpu::Model loadModel(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes = nullptr,
                          const std::string& assetRoot = {}, bool props = true);

// The clip `clip` names (by name, or by index), or the model's default clip when `clip` is empty.
// Throws Error listing the model's clips.
std::uint32_t clipIndex(const crowdgpu::Model& model, const std::string& clip);

// --model's list: NAME[:WEIGHT],... with positive weights (1 when left out). Throws Error.
std::vector<std::pair<std::string, float>> parseModelList(const std::string& list);

// The models of a crowd and each one's share of it.
struct CrowdModels {
    std::vector<crowdgpu::Model> models;
    std::vector<float> weights;
};
// "soldier+horse": the models' own names, for reports.
std::string modelNames(const CrowdModels& models);
CrowdModels loadModels(const std::string& list, std::uint32_t seed, std::vector<std::string>* notes = nullptr,
                       const std::string& assetRoot = {}, bool props = true);

// The crowd of the scene options: a grid (crowdgpu::Crowd::grid) of the models by weight, the clip
// by name or index or random, doing the scene's behaviour (seeded by its seed). In a crowd of several
// models, a named clip a model lacks leaves it its default clip, and models far from human size
// (under 0.1 or over 10 units tall, as some glTF files are) are scaled to 1.8 units so that they
// stand together. Living crowds (march, mill) also vary each character's scale by up to 8 % and its
// colour a little.
crowdgpu::Crowd buildCrowd(const CrowdModels& models, const SceneOptions& scene);

// The library's settings for the programs' options (the render target's formats are the library's
// defaults, which the programs' target uses; `antiAliasing` is --aa's).
crowdgpu::RendererSettings rendererSettings(const CullOptions& cull, crowdgpu::Method method,
                                            crowdgpu::Animation animation, bool shadows, std::uint32_t meshCapacity,
                                            AntiAliasing antiAliasing);

// Device memory a run takes: the library's memoryNeeded for the crowd and settings, and the
// programs' render target of `size`.
std::uint64_t estimateCrowdBytes(const HostDevice& device, const crowdgpu::Crowd& crowd,
                                 const crowdgpu::RendererSettings& settings, VkExtent2D size);
// Throws a one-line Error naming the flag to change when the device cannot render the target's
// sample count (--aa), the run cannot fit in the device's memory, or a buffer the crowd binds whole as a storage buffer is over the device's range.
void checkCrowdFits(const HostDevice& device, const crowdgpu::Crowd& crowd, const crowdgpu::RendererSettings& settings,
                    VkExtent2D size);
// The largest image size at most `wanted`, of its shape, that the crowd can be drawn into on this device:
// within its memory (estimateCrowdBytes), the limits of every image of the target
// (RenderTarget::limitProblem) and of what recordCompute draws (crowdgpu::viewportProblem). `wanted`
// when it fits; a window of any size is then drawn at this size and scaled to the window (crowd-view).
struct FittingSize {
    VkExtent2D size;
    std::string why;  // what `wanted` is past, in one line (empty when it fits)
};
FittingSize largestFittingSize(const HostDevice& device, const crowdgpu::Crowd& crowd,
                               const crowdgpu::RendererSettings& settings, VkExtent2D wanted);

// Animation time of frame `index`: a fixed 60 Hz step from `start` seconds, so runs are reproducible.
inline double frameTime(std::uint32_t index, double start = 0.0) { return start + static_cast<double>(index) / 60.0; }

}  // namespace app
