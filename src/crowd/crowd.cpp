#include "crowd/crowd.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "crowd/worker_pool.h"

namespace crowd {

std::uint32_t defaultClip(const model::SkinnedModel& model) {
    const int walk = model.findClip("walk");
    return walk >= 0 ? static_cast<std::uint32_t>(walk) : 0u;
}

std::vector<Character> gridLayout(const model::SkinnedModel& model, const LayoutOptions& options) {
    const glm::vec3 extent = model.boundsMax - model.boundsMin;
    // Room for the widest side of the model plus a gap, so neighbours never intersect.
    const float spacing = std::max(extent.x, extent.z) * 1.25f + 0.3f;
    const auto columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(options.count))));
    const auto rows = (options.count + columns - 1) / columns;
    const std::uint32_t clip = options.clip >= 0 ? static_cast<std::uint32_t>(options.clip) : defaultClip(model);

    std::mt19937 random(options.seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Character> characters(options.count);
    for (std::uint32_t i = 0; i < options.count; ++i) {
        Character& c = characters[i];
        const float x = (static_cast<float>(i % columns) - 0.5f * static_cast<float>(columns - 1)) * spacing;
        const float z = (static_cast<float>(i / columns) - 0.5f * static_cast<float>(rows - 1)) * spacing;
        c.clip = options.randomClips ? static_cast<std::uint32_t>(random() % model.clips.size()) : clip;
        const float duration = model.clips.empty() ? 1.0f : model.clips[c.clip].duration;
        c.timeOffset = unit(random) * duration;
        c.speed = 0.9f + 0.2f * unit(random);
        c.position = glm::vec3(x + (unit(random) - 0.5f) * 0.15f * spacing, 0.0f,
                               z + (unit(random) - 0.5f) * 0.15f * spacing);
        c.heading = (unit(random) - 0.5f) * 0.5f;
    }
    return characters;
}

glm::mat4 characterTransform(const Character& character) {
    const glm::mat4 translate = glm::translate(glm::mat4(1.0f), character.position);
    return glm::rotate(translate, character.heading, glm::vec3(0.0f, 1.0f, 0.0f));
}

Crowd::Crowd(const model::SkinnedModel& model, std::vector<Character> characters)
    : model_(model), characters_(std::move(characters)) {}

void Crowd::animateCharacter(std::uint32_t index, float time, std::span<gpu::BoneRows> out) const {
    const anim::Skeleton& skeleton = model_.skeleton;
    const std::size_t joints = skeleton.jointCount();
    // Per-thread scratch, reused by the pool's long-lived threads: once warm, animation allocates nothing.
    thread_local std::vector<anim::Transform> locals;
    thread_local std::vector<glm::mat4> modelSpace;
    locals.resize(joints);
    modelSpace.resize(joints);
    const Character& c = characters_[index];
    if (model_.clips.empty()) {
        std::copy(skeleton.restPose.begin(), skeleton.restPose.end(), locals.begin());
    } else {
        anim::sampleClip(model_.clips[c.clip], c.timeOffset + time * c.speed, skeleton.restPose, locals);
    }
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, characterTransform(c), out.first(joints));
}

void Crowd::animate(float time, std::span<gpu::BoneRows> out, std::uint32_t boneStride) const {
    // Chunks of 32 characters (tens of microseconds each) keep the handoff cost small and the cores even.
    WorkerPool::shared().parallelFor(size(), 32, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i)
            animateCharacter(i, time, out.subspan(static_cast<std::size_t>(i) * boneStride, boneStride));
    });
}

glm::vec3 Crowd::center() const {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Character& c : characters_) lo = glm::min(lo, c.position), hi = glm::max(hi, c.position);
    return characters_.empty() ? glm::vec3(0.0f) : 0.5f * (lo + hi);
}

float Crowd::radius() const {
    const glm::vec3 mid = center();
    float r = 0.0f;
    for (const Character& c : characters_) r = std::max(r, glm::length(c.position - mid));
    const glm::vec3 extent = model_.boundsMax - model_.boundsMin;
    return r + 0.5f * std::max(extent.x, extent.z);
}

}  // namespace crowd
