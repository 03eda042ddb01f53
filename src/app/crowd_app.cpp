#include "app/crowd_app.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "anim/local_to_model.h"
#include "app/memory_shortfall.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "crowd/pose_bounds.h"
#include "frame/memory_plan.h"
#include "gpu/buffer.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "model/lod_builder.h"
#include "model/procedural_models.h"
#include "render/crowd_buffers.h"
#include "render/draw_lists.h"
#include "render/geometry_pool.h"
#include "render/impostor_atlas.h"
#include "skin/skin_target_layout.h"
#include "skin/skinned_capacity.h"
#include "skin/storage_ranges.h"

namespace app {

namespace {

model::SkinnedModel loadMesh(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes,
                             const std::string& assetRoot) {
    if (name == "soldier") return model::makeSoldier(seed);
    if (name == "horse") return model::makeHorse(seed);
    std::error_code error;
    if (model::hasGltfExtension(name) || std::filesystem::is_regular_file(name, error))
        return model::loadGltf(name, notes, assetRoot);
    throw gpu::Error("--model: unknown model '" + name + "' (soldier, horse, or a .gltf/.glb file)");
}

int resolveClip(const model::SkinnedModel& model, const std::string& clip) {
    if (clip.empty()) return -1;
    if (const int byName = model.findClip(clip); byName >= 0) return byName;
    unsigned index = 0;
    const auto [ptr, error] = std::from_chars(clip.data(), clip.data() + clip.size(), index);
    if (error == std::errc() && ptr == clip.data() + clip.size() && index < model.clips.size())
        return static_cast<int>(index);
    std::string names;
    for (const anim::Clip& c : model.clips) names += (names.empty() ? "" : ", ") + c.name;
    throw gpu::Error("--clip: " + model.name + " has no clip '" + clip + "' (clips: " + names + ", or an index)");
}

}  // namespace

model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes,
                              const std::string& assetRoot) {
    model::SkinnedModel model = loadMesh(name, seed, notes, assetRoot);
    model::buildLods(model);
    model.poseSphere = crowd::computePoseSphere(model);
    return model;
}

std::uint32_t clipIndex(const model::SkinnedModel& model, const std::string& clip) {
    const int index = resolveClip(model, clip);
    return index >= 0 ? static_cast<std::uint32_t>(index) : crowd::defaultClip(model);
}

std::vector<skin::CpuSkinnedVertex> poseOnCpu(const model::SkinnedModel& model, std::uint32_t clip, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.restPose);
    if (clip < model.clips.size()) anim::sampleClip(model.clips[clip], time, skeleton.restPose, locals);
    std::vector<glm::mat4> modelSpace(skeleton.jointCount());
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    std::vector<gpu::BoneRows> bones(skeleton.jointCount());
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, glm::mat4(1.0f), bones);
    return skin::skinOnCpu(model, bones);
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
                    throw gpu::Error("--model: the weight of '" + item + "' must be a positive number");
                weight = value;
                item = item.substr(0, colon);
            }
        }
        if (item.empty()) throw gpu::Error("--model: empty model name in '" + list + "'");
        entries.emplace_back(item, weight);
        begin = comma + 1;
    }
    if (entries.size() > MAX_MODELS)
        throw gpu::Error("--model: at most " + std::to_string(MAX_MODELS) + " models in one crowd");
    return entries;
}

std::vector<const model::SkinnedModel*> CrowdModels::pointers() const {
    std::vector<const model::SkinnedModel*> result;
    for (const auto& m : models) result.push_back(m.get());
    return result;
}

std::string modelNames(const CrowdModels& models) {
    std::string names;
    for (const auto& m : models.models) names += (names.empty() ? "" : "+") + m->name;
    return names;
}

CrowdModels loadModels(const std::string& list, std::uint32_t seed, std::vector<std::string>* notes,
                       const std::string& assetRoot) {
    CrowdModels result;
    for (const auto& [name, weight] : parseModelList(list)) {
        result.models.push_back(std::make_unique<model::SkinnedModel>(loadModel(name, seed, notes, assetRoot)));
        result.weights.push_back(weight);
    }
    return result;
}

std::vector<crowd::Character> buildCharacters(const CrowdModels& models, const SceneOptions& scene) {
    crowd::LayoutOptions layout;
    layout.count = scene.count;
    layout.seed = scene.seed;
    layout.randomClips = scene.clip == "random";
    layout.weights = models.weights;
    const bool several = models.models.size() > 1;
    for (const auto& m : models.models) {
        int clip = -1;
        if (!layout.randomClips) {
            try {
                clip = resolveClip(*m, scene.clip);
            } catch (const gpu::Error&) {
                if (!several) throw;
            }
        }
        layout.clips.push_back(clip);
        const float height = m->height();
        layout.scales.push_back(several && height > 0.0f && (height < 0.1f || height > 10.0f) ? 1.8f / height : 1.0f);
    }
    const bool living = scene.behaviour != crowd::Behaviour::InPlace;
    layout.formation = scene.behaviour == crowd::Behaviour::March;
    layout.scaleVariation = living ? 0.08f : 0.0f;
    layout.tintVariation = living ? 0.12f : 0.0f;
    return crowd::gridLayout(models.pointers(), layout);
}

crowd::Crowd buildCrowd(const CrowdModels& models, const SceneOptions& scene) {
    crowd::BehaviourSettings behaviour;
    behaviour.kind = scene.behaviour;
    behaviour.seed = scene.seed;
    return crowd::Crowd(models.pointers(), buildCharacters(models, scene), behaviour);
}

std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const SceneOptions& scene) {
    crowd::LayoutOptions layout;
    layout.count = scene.count;
    layout.seed = scene.seed;
    layout.randomClips = scene.clip == "random";
    layout.clips = {layout.randomClips ? -1 : resolveClip(model, scene.clip)};
    const model::SkinnedModel* models[1] = {&model};
    return crowd::gridLayout(models, layout);
}

namespace {

// The render target's colour and depth (8 bytes a pixel).
std::uint64_t imageBytes(VkExtent2D size) { return static_cast<std::uint64_t>(size.width) * size.height * 8; }

}  // namespace

std::uint64_t estimateCrowdBytes(const gpu::VulkanContext& context, const crowd::Crowd& crowd, skin::Method method,
                                 VkExtent2D size, std::uint32_t meshCapacity) {
    // The library's own planner (what its renderer will allocate), and the programs' render target.
    frame::RecorderOptions options;
    options.method = method;
    options.cull.impostors = meshCapacity > 0;
    options.meshCapacity = meshCapacity;
    return frame::planMemory(context, crowd, options).total() + imageBytes(size);
}

void checkCrowdFits(const gpu::VulkanContext& context, const crowd::Crowd& crowd, skin::Method method, VkExtent2D size,
                    std::uint32_t meshCapacity) {
    const std::uint64_t needed = estimateCrowdBytes(context, crowd, method, size, meshCapacity);
    const std::uint64_t available = context.deviceLocalBytes();
    if (needed > available)
        throw gpu::Error(describeShortfall({crowd.size(), size, skin::methodName(method), needed, imageBytes(size),
                                            available, context.description.name}));
    skin::checkStorageRanges(context.properties.limits, crowd, method, meshCapacity);
}

render::CrowdShape crowdShape(const crowd::Crowd& crowd) {
    return {crowd.center(), crowd.radius(), crowd.tallestHeight()};
}

}  // namespace app
