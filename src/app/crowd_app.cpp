#include "app/crowd_app.h"

#include <charconv>
#include <filesystem>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "gpu/buffer.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "model/gltf_loader.h"
#include "model/procedural_models.h"
#include "skin/fragment_skinning.h"

namespace app {

model::SkinnedModel loadModel(const std::string& name, std::uint32_t seed, std::vector<std::string>* notes,
                              const std::string& assetRoot) {
    if (name == "soldier") return model::makeSoldier(seed);
    if (name == "horse") return model::makeHorse(seed);
    std::error_code error;
    if (model::hasGltfExtension(name) || std::filesystem::is_regular_file(name, error))
        return model::loadGltf(name, notes, assetRoot);
    throw gpu::Error("--model: unknown model '" + name + "' (soldier, horse, or a .gltf/.glb file)");
}

namespace {

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

std::vector<crowd::Character> buildCharacters(const model::SkinnedModel& model, const SceneOptions& scene) {
    crowd::LayoutOptions layout;
    layout.count = scene.count;
    layout.seed = scene.seed;
    layout.randomClips = scene.clip == "random";
    layout.clip = layout.randomClips ? -1 : resolveClip(model, scene.clip);
    return crowd::gridLayout(model, layout);
}

void checkCrowdFits(const gpu::VulkanContext& context, const model::SkinnedModel& model, std::uint32_t count,
                    skin::Method method, VkExtent2D size) {
    const auto vertices = static_cast<std::uint32_t>(model.vertices.size());
    const std::uint64_t boneBytes = static_cast<std::uint64_t>(count) *
                                    render::boneStrideFor(context, static_cast<std::uint32_t>(model.skeleton.jointCount())) *
                                    sizeof(gpu::BoneRows);
    const std::uint64_t needed = boneBytes +
                                 skin::estimateMethodBytes(method, vertices, count, skin::maxSkinTargetDimension(context, 0)) +
                                 static_cast<std::uint64_t>(size.width) * size.height * 8;
    const std::uint64_t available = context.deviceLocalBytes();
    if (needed > available)
        throw gpu::Error("--count " + std::to_string(count) + ": " + skin::methodName(method) + " needs about " +
                         gpu::formatBytes(needed) + " of device memory; " + context.description.name + " has " +
                         gpu::formatBytes(available));
}

}  // namespace app
