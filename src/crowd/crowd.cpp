#include "crowd/crowd.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "crowd/worker_pool.h"
#include "gpu/vulkan_error.h"

namespace crowd {

std::uint32_t defaultClip(const model::SkinnedModel& model) {
    const int walk = model.findClip("walk");
    return walk >= 0 ? static_cast<std::uint32_t>(walk) : 0u;
}

float brightnessVariation(std::uint32_t index) {
    std::uint32_t h = index * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return 0.82f + 0.36f * static_cast<float>(h & 1023u) / 1023.0f;
}

namespace {

float widestFootprint(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options) {
    float widest = 0.0f;
    for (std::size_t m = 0; m < models.size(); ++m) {
        const glm::vec3 extent = models[m]->boundsMax - models[m]->boundsMin;
        const float scale = m < options.scales.size() ? options.scales[m] : 1.0f;
        widest = std::max(widest, std::max(extent.x, extent.z) * scale);
    }
    return widest;
}

std::uint32_t clipFor(const model::SkinnedModel& model, std::uint32_t modelIndex, const LayoutOptions& options,
                      std::mt19937& random) {
    if (model.clips.empty()) return 0;
    if (options.randomClips) return static_cast<std::uint32_t>(random() % model.clips.size());
    const int clip = modelIndex < options.clips.size() ? options.clips[modelIndex] : -1;
    return clip >= 0 ? static_cast<std::uint32_t>(clip) : defaultClip(model);
}

}  // namespace

std::vector<Character> gridLayout(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options) {
    // Room for the widest side of any model plus a gap, so neighbours never intersect.
    const float spacing = widestFootprint(models, options) * 1.25f + 0.3f;
    const auto columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(options.count))));
    const auto rows = (options.count + columns - 1) / columns;
    std::vector<float> weights = options.weights;
    weights.resize(models.size(), weights.empty() ? 1.0f : 0.0f);

    std::mt19937 random(options.seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::discrete_distribution<std::uint32_t> pickModel(weights.begin(), weights.end());
    std::vector<Character> characters(options.count);
    for (std::uint32_t i = 0; i < options.count; ++i) {
        Character& c = characters[i];
        // One model keeps the random sequence of the single-model layout, so its crowds stay as they were.
        c.model = models.size() > 1 ? pickModel(random) : 0u;
        const model::SkinnedModel& model = *models[c.model];
        const float x = (static_cast<float>(i % columns) - 0.5f * static_cast<float>(columns - 1)) * spacing;
        const float z = (static_cast<float>(i / columns) - 0.5f * static_cast<float>(rows - 1)) * spacing;
        c.clip = clipFor(model, c.model, options, random);
        const float duration = model.clips.empty() ? 1.0f : model.clips[c.clip].duration;
        c.timeOffset = unit(random) * duration;
        c.speed = 0.9f + 0.2f * unit(random);
        c.position = glm::vec3(x + (unit(random) - 0.5f) * 0.15f * spacing, 0.0f,
                               z + (unit(random) - 0.5f) * 0.15f * spacing);
        c.heading = (unit(random) - 0.5f) * 0.5f;
        c.scale = c.model < options.scales.size() ? options.scales[c.model] : 1.0f;
        c.tint = glm::vec3(brightnessVariation(i));
    }
    return characters;
}

glm::mat4 characterTransform(const Character& character) {
    const glm::mat4 translate = glm::translate(glm::mat4(1.0f), character.position);
    const glm::mat4 turn = glm::rotate(translate, character.heading, glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::scale(turn, glm::vec3(character.scale));
}

Crowd::Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters)
    : models_(std::move(models)), characters_(std::move(characters)) {
    if (models_.empty() || models_.size() > MAX_MODELS)
        throw gpu::Error("a crowd holds 1 to " + std::to_string(MAX_MODELS) + " models, not " +
                         std::to_string(models_.size()));
    for (std::size_t i = 0; i < characters_.size(); ++i) {
        const Character& c = characters_[i];
        if (c.model >= models_.size())
            throw gpu::Error("character " + std::to_string(i) + " names model " + std::to_string(c.model) +
                             " of " + std::to_string(models_.size()));
        const model::SkinnedModel& m = *models_[c.model];
        if (!m.clips.empty() && c.clip >= m.clips.size())
            throw gpu::Error("character " + std::to_string(i) + " names clip " + std::to_string(c.clip) + " of " +
                             m.name + ", which has " + std::to_string(m.clips.size()));
    }
}

Crowd::Crowd(const model::SkinnedModel& model, std::vector<Character> characters)
    : Crowd(std::vector<const model::SkinnedModel*>{&model}, std::move(characters)) {}

void Crowd::animateCharacter(std::uint32_t index, float time, std::span<gpu::BoneRows> out) const {
    const Character& c = characters_[index];
    const model::SkinnedModel& model = *models_[c.model];
    const anim::Skeleton& skeleton = model.skeleton;
    const std::size_t joints = skeleton.jointCount();
    // Per-thread scratch, reused by the pool's long-lived threads: once warm, animation allocates nothing.
    thread_local std::vector<anim::Transform> locals;
    thread_local std::vector<glm::mat4> modelSpace;
    locals.resize(joints);
    modelSpace.resize(joints);
    if (model.clips.empty()) {
        std::copy(skeleton.restPose.begin(), skeleton.restPose.end(), locals.begin());
    } else {
        anim::sampleClip(model.clips[c.clip], c.timeOffset + time * c.speed, skeleton.restPose, locals);
    }
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, characterTransform(c), out.first(joints));
}

void Crowd::animate(float time, std::span<gpu::BoneRows> out, std::span<const std::uint32_t> boneOffsets) const {
    // Chunks of 32 characters (tens of microseconds each) keep the handoff cost small and the cores even.
    WorkerPool::shared().parallelFor(size(), 32, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) animateCharacter(i, time, out.subspan(boneOffsets[i]));
    });
}

glm::vec3 Crowd::center() const {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Character& c : characters_) lo = glm::min(lo, c.position), hi = glm::max(hi, c.position);
    return characters_.empty() ? glm::vec3(0.0f) : 0.5f * (lo + hi);
}

float Crowd::radius() const {
    const glm::vec3 mid = center();
    float r = 0.0f, widest = 0.0f;
    for (const Character& c : characters_) r = std::max(r, glm::length(c.position - mid));
    for (const model::SkinnedModel* m : models_) {
        const glm::vec3 extent = m->boundsMax - m->boundsMin;
        widest = std::max(widest, std::max(extent.x, extent.z));
    }
    return r + 0.5f * widest;
}

float Crowd::tallestHeight() const {
    float tallest = 0.0f;
    for (const Character& c : characters_) tallest = std::max(tallest, models_[c.model]->height() * c.scale);
    return characters_.empty() ? models_[0]->height() : tallest;
}

}  // namespace crowd
