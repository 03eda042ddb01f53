#include "app/crowd_app.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "app/error.h"
#include "app/host_device.h"
#include "app/memory_shortfall.h"
#include "app/render_target.h"

namespace app {
namespace {

// The library's words for the command line's: it names its arguments, the programs their flags.
std::string inFlagWords(std::string message) {
    const std::string libraryWords = "(a wider asset root, the assetRoot argument, allows it)";
    if (const std::size_t at = message.find(libraryWords); at != std::string::npos)
        message.replace(at, libraryWords.size(), "(--asset-root DIR allows a wider one)");
    return message;
}

crowdgpu::Model loadNamed(const std::string& name, std::uint32_t seed, const std::string& assetRoot, bool props) {
    if (name == "soldier") return crowdgpu::Model::soldier(seed, props);
    if (name == "horse") return crowdgpu::Model::horse(seed);
    if (name == "cavalry") return crowdgpu::Model::cavalry(seed);
    std::error_code error;
    const std::string extension = std::filesystem::path(name).extension().string();
    if (extension == ".gltf" || extension == ".glb" || std::filesystem::is_regular_file(name, error)) {
        try {
            return crowdgpu::Model::fromGltf(name, assetRoot);
        } catch (const crowdgpu::Error& e) {
            throw Error(inFlagWords(e.what()));
        }
    }
    throw Error("--model: unknown model '" + name + "' (soldier, horse, cavalry, or a .gltf/.glb file)");
}

// The clip's index, -1 for "" (the default clip).
int resolveClip(const crowdgpu::Model& model, const std::string& clip) {
    if (clip.empty()) return -1;
    if (const int byName = model.findClip(clip); byName >= 0) return byName;
    unsigned index = 0;
    const auto [ptr, error] = std::from_chars(clip.data(), clip.data() + clip.size(), index);
    if (error == std::errc() && ptr == clip.data() + clip.size() && index < model.clipCount())
        return static_cast<int>(index);
    std::string names;
    for (std::uint32_t c = 0; c < model.clipCount(); ++c) names += (names.empty() ? "" : ", ") + model.clipName(c);
    throw Error("--clip: " + model.name() + " has no clip '" + clip + "' (clips: " + names + ", or an index)");
}

}  // namespace

crowdgpu::Model loadModel(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes,
                          const std::string& assetRoot, bool props) {
    crowdgpu::Model model = loadNamed(name, seed, assetRoot, props);
    if (notes) notes->insert(notes->end(), model.notes().begin(), model.notes().end());
    return model;
}

std::uint32_t clipIndex(const crowdgpu::Model& model, const std::string& clip) {
    const int index = resolveClip(model, clip);
    return index >= 0 ? static_cast<std::uint32_t>(index) : model.defaultClip();
}

std::vector<std::pair<std::string, float>> parseModelList(const std::string& list) {
    std::vector<std::pair<std::string, float>> entries;
    std::size_t begin = 0;
    while (begin <= list.size()) {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        std::string item = list.substr(begin, comma - begin);
        float weight = 1.0f;
        // A weight follows the last colon, unless what follows is no number (a path may hold colons).
        if (const std::size_t colon = item.rfind(':'); colon != std::string::npos) {
            const std::string text = item.substr(colon + 1);
            float value = 0.0f;
            const auto [ptr, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (!text.empty() && error == std::errc() && ptr == text.data() + text.size()) {
                if (!(value > 0.0f) || !std::isfinite(value))
                    throw Error("--model: the weight of '" + item + "' must be a positive number");
                weight = value;
                item = item.substr(0, colon);
            }
        }
        if (item.empty()) throw Error("--model: empty model name in '" + list + "'");
        entries.emplace_back(item, weight);
        begin = comma + 1;
    }
    if (entries.size() > crowdgpu::kMaxCrowdModels)
        throw Error("--model: at most " + std::to_string(crowdgpu::kMaxCrowdModels) + " models in one crowd");
    return entries;
}

std::string modelNames(const CrowdModels& models) {
    std::string names;
    for (const crowdgpu::Model& m : models.models) names += (names.empty() ? "" : "+") + m.name();
    return names;
}

CrowdModels loadModels(const std::string& list, std::uint32_t seed, std::vector<std::string>* notes,
                       const std::string& assetRoot, bool props) {
    CrowdModels result;
    for (const auto& [name, weight] : parseModelList(list)) {
        result.models.push_back(loadModel(name, seed, notes, assetRoot, props));
        result.weights.push_back(weight);
    }
    return result;
}

crowdgpu::Crowd buildCrowd(const CrowdModels& models, const SceneOptions& scene) {
    crowdgpu::GridLayout layout;
    layout.count = scene.count;
    layout.seed = scene.seed;
    layout.randomClips = scene.clip == "random";
    layout.weights = models.weights;
    const bool several = models.models.size() > 1;
    for (const crowdgpu::Model& m : models.models) {
        int clip = -1;
        if (!layout.randomClips) {
            try {
                clip = resolveClip(m, scene.clip);
            } catch (const Error&) {
                if (!several) throw;
            }
        }
        layout.clips.push_back(clip);
        const float height = m.height();
        layout.scales.push_back(several && height > 0.0f && (height < 0.1f || height > 10.0f) ? 1.8f / height : 1.0f);
    }
    const bool living = scene.behaviour != crowdgpu::Behaviour::InPlace;
    layout.formation = scene.behaviour == crowdgpu::Behaviour::March;
    layout.depthRatio = scene.depthRatio;
    layout.scaleVariation = living ? 0.08f : 0.0f;
    layout.tintVariation = living ? 0.12f : 0.0f;
    layout.props = scene.props;
    // The agents' characters are theirs from the start (--agents); a crowd no one drives keeps no keys.
    const WorldOptions::Agents agents = scene.world.agents;
    layout.motion = agents == WorldOptions::Agents::Host     ? crowdgpu::MotionSource::HostSamples
                    : agents == WorldOptions::Agents::Device ? crowdgpu::MotionSource::DeviceSamples
                                                             : crowdgpu::MotionSource::Behaviour;
    // Driven characters get their keys (the capacity's default); a crowd no one drives keeps none.
    return crowdgpu::Crowd::grid(models.models, layout, scene.behaviour);
}

crowdgpu::RendererSettings rendererSettings(const CullOptions& cull, crowdgpu::Method method,
                                            crowdgpu::Animation animation, bool shadows, std::uint32_t meshCapacity,
                                            AntiAliasing antiAliasing) {
    crowdgpu::RendererSettings settings;
    settings.target.samples = antiAliasing.samples;
    settings.edgeFilter = antiAliasing.edgeFilter;
    settings.method = method;
    settings.animation = animation;
    settings.culling = cull.mode;
    settings.lod = cull.lod;
    settings.lodThresholds[0] = cull.lodThresholds[0];
    settings.lodThresholds[1] = cull.lodThresholds[1];
    settings.lodHysteresis = cull.hysteresis;
    settings.impostors = cull.impostors;
    settings.impostorThreshold = cull.impostorThreshold;
    settings.meshCapacity = meshCapacity;
    settings.shadows = shadows;
    settings.shadowLod = cull.shadowLod;
    settings.shadowRaster = cull.shadowRaster;
    settings.shadowCascades = cull.shadowCascades;
    settings.lodFade = cull.lodFade;
    settings.impostorBlend = cull.impostorBlend;
    settings.farCrowd = cull.farCrowd;
    settings.raster = cull.raster;
    settings.meshRasterLimit = cull.meshRasterLimit;
    settings.events = cull.events;
    settings.ground = true;  // the programs' frame: the ground behind the characters (recordCharacters)
    settings.sky = true;     // and the sky where nothing is, so the target's colour is not cleared
    return settings;
}

std::uint64_t estimateCrowdBytes(const HostDevice& device, const crowdgpu::Crowd& crowd,
                                 const crowdgpu::RendererSettings& settings, VkExtent2D size) {
    // The compute rasterizer's visibility buffers follow the target (8 bytes a pixel, one a frame in flight),
    // which the library's plan does not know; with the far crowd averaged, its layer's too (an 8-byte
    // depth word and eight 4-byte sums a pixel: FAR_CROWD_CHANNELS in shaders/gpu_types.h).
    const std::uint64_t perPixel = 8u + (settings.farCrowd ? 8u + 8u * 4u : 0u);
    const std::uint64_t visibility = settings.impostors && settings.raster != crowdgpu::Raster::Hardware
                                         ? std::uint64_t{size.width} * size.height * perPixel * settings.framesInFlight
                                         : 0u;
    return crowdgpu::memoryNeeded(device.physicalDevice, crowd, settings) + renderTargetBytes(size, settings.target.samples, settings.edgeFilter) +
           visibility;
}

// The image's size against what the renderer's recordCompute draws (crowdgpu::viewportProblem), in the
// command line's words.
static void checkViewport(const HostDevice& device, const crowdgpu::RendererSettings& settings, VkExtent2D size) {
    std::string problem = crowdgpu::viewportProblem(device.physicalDevice, settings, size);
    if (problem.empty()) return;
    for (const std::string words : {"raster compute", "raster auto"})
        if (const std::size_t at = problem.find(words); at != std::string::npos) problem.insert(at, "--");
    throw Error("--size " + std::to_string(size.width) + "x" + std::to_string(size.height) + ": " + problem);
}

FittingSize largestFittingSize(const HostDevice& device, const crowdgpu::Crowd& crowd,
                               const crowdgpu::RendererSettings& settings, VkExtent2D wanted) {
    auto scaled = [&](double scale) {
        return VkExtent2D{std::max(1u, static_cast<std::uint32_t>(wanted.width * scale)),
                          std::max(1u, static_cast<std::uint32_t>(wanted.height * scale))};
    };
    auto problem = [&](VkExtent2D size) -> std::string {
        const std::uint64_t needed = estimateCrowdBytes(device, crowd, settings, size);
        if (needed > device.deviceLocalBytes())
            return "it needs " + std::to_string(needed >> 20) + " MiB of device memory, " + device.description.name +
                   " has " + std::to_string(device.deviceLocalBytes() >> 20) + " MiB";
        if (std::string limit = RenderTarget::limitProblem(device, size, settings.target, settings.edgeFilter); !limit.empty())
            return limit;
        return crowdgpu::viewportProblem(device.physicalDevice, settings, size);
    };
    FittingSize result{wanted, problem(wanted)};
    if (result.why.empty()) return result;
    // Every limit grows with the size, so the largest scale that fits is found by halving the interval
    // (to under a pixel of the longer side in 2^-20).
    double fitting = 0.0, failing = 1.0;
    for (int step = 0; step < 20; ++step) {
        const double middle = 0.5 * (fitting + failing);
        (problem(scaled(middle)).empty() ? fitting : failing) = middle;
    }
    result.size = scaled(fitting);
    return result;
}

void checkCrowdFits(const HostDevice& device, const crowdgpu::Crowd& crowd, const crowdgpu::RendererSettings& settings,
                    VkExtent2D size) {
    checkAntiAliasing(device, settings.target.samples);
    const std::uint64_t needed = estimateCrowdBytes(device, crowd, settings, size);
    const std::uint64_t available = device.deviceLocalBytes();
    if (needed > available)
        throw Error(describeShortfall({crowd.size(), size, crowdgpu::methodName(settings.method), needed,
                                       renderTargetBytes(size, settings.target.samples, settings.edgeFilter), available, device.description.name}));
    const crowdgpu::DeviceLimitCheck limits = crowdgpu::checkDeviceLimits(device.physicalDevice, crowd, settings);
    if (limits.problem.empty()) {
        checkViewport(device, settings, size);
        return;
    }
    const std::string flag = limits.meshCapacityBound ? "--mesh-capacity " + std::to_string(settings.meshCapacity)
                                                      : "--count " + std::to_string(crowd.size());
    std::string message = limits.problem;
    const std::string capacityWords = "a mesh capacity of";
    for (std::size_t at = message.find(capacityWords); at != std::string::npos; at = message.find(capacityWords, at))
        message.replace(at, capacityWords.size(), "a --mesh-capacity of"), at += capacityWords.size();
    throw Error(flag + ": " + message);
}

}  // namespace app
