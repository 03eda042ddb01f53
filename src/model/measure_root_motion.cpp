#include "model/measure_root_motion.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "model/clip_skinning.h"

namespace model {
namespace {

// Steps per root-motion sample: finer than the curve so the median sees small, clean displacements.
constexpr int kSubsteps = 4;
constexpr int kSteps = ROOT_MOTION_SAMPLES * kSubsteps;
// Planted: within this fraction of the model's height of the lowest vertex.
constexpr float kGroundBand = 0.02f;
// Poses either side of a step in which a vertex must stay on the ground to count as planted.
constexpr int kPlantedWindow = 2;
// Clips that move less than this fraction of the model's height per cycle are in place (idle).
constexpr float kInPlace = 0.02f;

std::vector<glm::vec3> skinnedPositions(const SkinnedModel& model, const anim::Clip& clip, float time) {
    const std::vector<glm::mat4> global = clipSkinningMatrices(model, clip, time);
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

// The body's move from pose i to pose i + 1 (poses wrap round the cycle): minus the median move of the
// vertices planted then, those within `band` of the ground (the lowest any vertex gets over the
// cycle) in every pose from i - kPlantedWindow to i + 1 + kPlantedWindow: a foot resting on the
// ground, not a swinging one skimming past it.
std::optional<glm::vec2> bodyStep(const std::vector<std::vector<glm::vec3>>& poses, int i, float ground, float band) {
    const int steps = static_cast<int>(poses.size()) - 1;  // the last pose repeats the first
    auto pose = [&](int k) -> const std::vector<glm::vec3>& { return poses[static_cast<std::size_t>(((k % steps) + steps) % steps)]; };
    std::vector<float> dx, dz;
    for (std::size_t v = 0; v < poses[0].size(); ++v) {
        bool planted = true;
        for (int k = i - kPlantedWindow; k <= i + 1 + kPlantedWindow && planted; ++k) planted = pose(k)[v].y <= ground + band;
        if (!planted) continue;
        dx.push_back(pose(i)[v].x - pose(i + 1)[v].x);
        dz.push_back(pose(i)[v].z - pose(i + 1)[v].z);
    }
    if (dx.empty()) return std::nullopt;
    return glm::vec2(median(dx), median(dz));
}

}  // namespace

anim::RootMotion measureRootMotion(const SkinnedModel& model, const anim::Clip& clip) {
    anim::RootMotion motion;
    if (!(clip.duration > 0.0f) || model.vertices.empty()) return motion;
    const float footing = model.footingHeight > 0.0f ? model.footingHeight : model.height();
    const float band = kGroundBand * footing;
    std::vector<std::vector<glm::vec3>> poses;
    float ground = 1e30f;
    for (int i = 0; i <= kSteps; ++i) {
        poses.push_back(skinnedPositions(model, clip, clip.duration * static_cast<float>(i) / kSteps));
        for (const glm::vec3& p : poses.back()) ground = std::min(ground, p.y);
    }
    std::vector<std::optional<glm::vec2>> steps(kSteps);
    for (std::size_t i = 0; i < steps.size(); ++i) steps[i] = bodyStep(poses, static_cast<int>(i), ground, band);
    glm::vec2 known(0.0f);
    int knownCount = 0;
    for (const std::optional<glm::vec2>& step : steps)
        if (step) known += *step, ++knownCount;
    if (knownCount == 0) return motion;
    const glm::vec2 mean = known / static_cast<float>(knownCount);
    glm::vec2 total(0.0f);
    for (int i = 0; i < kSteps; ++i) {
        total += steps[static_cast<std::size_t>(i)].value_or(mean);
        if ((i + 1) % kSubsteps == 0) motion.samples[static_cast<std::size_t>((i + 1) / kSubsteps)] = total;
    }
    if (glm::length(total) < kInPlace * footing) return anim::RootMotion{};
    motion.stride = total;
    return motion;
}

}  // namespace model
