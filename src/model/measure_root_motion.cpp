#include "model/measure_root_motion.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"

namespace model {
namespace {

// Steps per root-motion sample: finer than the curve so the median sees small, clean displacements.
constexpr int kSubsteps = 4;
constexpr int kSteps = ROOT_MOTION_SAMPLES * kSubsteps;
// Planted: within this fraction of the model's height of the lowest vertex.
constexpr float kGroundBand = 0.02f;
// Clips that move less than this fraction of the model's height per cycle are in place (idle).
constexpr float kInPlace = 0.02f;

std::vector<glm::vec3> skinnedPositions(const SkinnedModel& model, const anim::Clip& clip, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.jointCount());
    std::vector<glm::mat4> global(skeleton.jointCount());
    anim::sampleClip(clip, time, skeleton.restPose, locals);
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, global);
    for (std::size_t j = 0; j < global.size(); ++j) global[j] = global[j] * skeleton.inverseBind[j];
    std::vector<glm::vec3> positions(model.vertices.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const gpu::SkinVertex& v = model.vertices[i];
        glm::vec4 p(0.0f);
        for (int k = 0; k < 4; ++k) p += v.weights[k] * (global[v.joints[k]] * v.position);
        positions[i] = glm::vec3(p);
    }
    return positions;
}

float median(std::vector<float>& values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The body's move between two poses: minus the median move of the vertices planted in both (within
// `band` of the ground, the lowest any vertex gets over the cycle).
std::optional<glm::vec2> bodyStep(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, float ground,
                                  float band) {
    std::vector<float> dx, dz;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].y > ground + band || b[i].y > ground + band) continue;
        dx.push_back(a[i].x - b[i].x);
        dz.push_back(a[i].z - b[i].z);
    }
    if (dx.empty()) return std::nullopt;
    return glm::vec2(median(dx), median(dz));
}

}  // namespace

anim::RootMotion measureRootMotion(const SkinnedModel& model, const anim::Clip& clip) {
    anim::RootMotion motion;
    if (!(clip.duration > 0.0f) || model.vertices.empty()) return motion;
    const float band = kGroundBand * model.height();
    std::vector<std::vector<glm::vec3>> poses;
    float ground = 1e30f;
    for (int i = 0; i <= kSteps; ++i) {
        poses.push_back(skinnedPositions(model, clip, clip.duration * static_cast<float>(i) / kSteps));
        for (const glm::vec3& p : poses.back()) ground = std::min(ground, p.y);
    }
    std::vector<std::optional<glm::vec2>> steps(kSteps);
    glm::vec2 direction(0.0f);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        steps[i] = bodyStep(poses[i], poses[i + 1], ground, band);
        if (steps[i]) direction += *steps[i];
    }
    // A step against the cycle's direction comes from a swinging foot grazing the ground, not a planted
    // one: the body never walks backwards within a forward gait, so such steps count as unknown.
    glm::vec2 known(0.0f);
    int knownCount = 0;
    for (std::optional<glm::vec2>& step : steps) {
        if (step && glm::dot(*step, direction) < 0.0f) step.reset();
        if (step) known += *step, ++knownCount;
    }
    if (knownCount == 0) return motion;
    const glm::vec2 mean = known / static_cast<float>(knownCount);
    glm::vec2 total(0.0f);
    for (int i = 0; i < kSteps; ++i) {
        total += steps[static_cast<std::size_t>(i)].value_or(mean);
        if ((i + 1) % kSubsteps == 0) motion.samples[static_cast<std::size_t>((i + 1) / kSubsteps)] = total;
    }
    if (glm::length(total) < kInPlace * model.height()) return anim::RootMotion{};
    motion.stride = total;
    return motion;
}

}  // namespace model
