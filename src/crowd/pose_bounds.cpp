#include "crowd/pose_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "skin/cpu_skinning.h"

namespace crowd {
namespace {

// Characters play clips at any phase and speed, so any time can be drawn. Sampling at the programs'
// frame rate leaves 17 ms between samples: a galloping hoof (about 10 m/s) moves 17 cm, and a path
// curving round a joint half a metre away leaves the chord between two samples (which the sphere
// holds, being convex) by under a centimetre, inside the 1 % margin of a character's radius (a
// horse's is 1.5 m, the soldier's 1 m). Key times are sampled too, since linear keys are where a
// joint turns back. Sampling twice as densely costs twice the skinning and grows none of our
// spheres by even 0.01 %.
constexpr float kSamplesPerSecond = 60.0f;
constexpr float kMargin = 0.01f;

std::vector<float> sampleTimes(const anim::Clip& clip) {
    // Clips loop over [0, duration): a key at the end shows as the last instant before it.
    const float last = std::max(0.0f, std::nextafter(clip.duration, 0.0f));
    std::vector<float> times;
    for (const anim::Channel& channel : clip.channels)
        for (float time : channel.times) times.push_back(std::clamp(time, 0.0f, last));
    const int uniform = std::max(1, static_cast<int>(std::ceil(clip.duration * kSamplesPerSecond)));
    for (int i = 0; i < uniform; ++i) times.push_back(clip.duration * static_cast<float>(i) / static_cast<float>(uniform));
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

// The model's vertices that differ in position or skin. Copies split only for normals, materials or
// texture coordinates skin to the same place (the Fox has 290 distinct of 1,728).
model::SkinnedModel distinctPositions(const model::SkinnedModel& model) {
    // Position, joints and weights as bits: equal bits skin equally.
    using Key = std::array<std::uint32_t, 12>;
    std::set<Key> seen;
    model::SkinnedModel distinct;
    for (const gpu::SkinVertex& v : model.vertices) {
        Key key;
        std::memcpy(key.data(), &v.position, 16);
        std::memcpy(key.data() + 4, &v.joints, 32);
        if (seen.insert(key).second) distinct.vertices.push_back(v);
    }
    return distinct;
}

// Appends the distinct vertices skinned in one pose: `clip` at `time`, or the rest pose without one.
void appendPose(const model::SkinnedModel& model, const model::SkinnedModel& distinct, const anim::Clip* clip,
                float time, std::vector<glm::dvec3>& points) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.restPose);
    if (clip) anim::sampleClip(*clip, time, skeleton.restPose, locals);
    std::vector<glm::mat4> modelSpace(skeleton.jointCount());
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    std::vector<gpu::BoneRows> bones(skeleton.jointCount());
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, glm::mat4(1.0f), bones);
    for (const skin::CpuSkinnedVertex& v : skin::skinOnCpu(distinct, bones)) points.push_back(v.position);
}

}  // namespace

glm::vec4 computePoseSphere(const model::SkinnedModel& model) {
    if (model.vertices.empty()) return glm::vec4(0.0f);
    const model::SkinnedModel distinct = distinctPositions(model);
    // The rest pose is what a character without a clip shows. (The bind pose itself is never drawn:
    // every method skins.)
    std::vector<glm::dvec3> points;
    appendPose(model, distinct, nullptr, 0.0f, points);
    for (const anim::Clip& clip : model.clips)
        for (float time : sampleTimes(clip)) appendPose(model, distinct, &clip, time, points);

    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::dvec3 center = 0.5 * (lo + hi);
    double radius = 0.0;
    for (const glm::dvec3& p : points) radius = std::max(radius, glm::length(p - center));
    return glm::vec4(glm::vec3(center), static_cast<float>(radius * (1.0 + kMargin)));
}

}  // namespace crowd
