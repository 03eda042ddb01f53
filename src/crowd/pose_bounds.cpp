#include "crowd/pose_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "anim/local_to_model.h"
#include "anim/pose_reach.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "model/attach_prop.h"
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
// At most this many poses of one clip are skinned (20 s of clip at 60 a second, keys included: every
// clip of the built-in and shared models is sampled in full). A longer clip would cost memory and time
// in proportion to its length (a 200 s CesiumMan clip: 12,000 poses), and one of 2e6 s would never
// finish; past this, its poses are sampled at this many evenly spaced times and the sphere is grown to
// hold anim::poseReach's bound, which holds every pose the clip can give, sampled or not.
constexpr double kMaxSamplesPerClip = 1200.0;

struct ClipSamples {
    std::vector<float> times;
    bool complete = true;  // every key time and 60 a second: the margin covers the poses between
};

ClipSamples sampleTimes(const anim::Clip& clip) {
    // Clips loop over [0, duration): a key at the end shows as the last instant before it.
    const float last = std::max(0.0f, std::nextafter(clip.duration, 0.0f));
    std::vector<float> keys;  // distinct key times (channels of a clip mostly share them)
    for (const anim::Channel& channel : clip.channels)
        for (float time : channel.times) keys.push_back(std::clamp(time, 0.0f, last));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    // In float as before (the same samples for every clip sampled in full), compared in double: no
    // cast of a count beyond int's range (a duration above 3.6e7 s) happens.
    const double wanted = std::max(1.0, static_cast<double>(std::ceil(clip.duration * kSamplesPerSecond)));
    ClipSamples samples;
    samples.complete = wanted + static_cast<double>(keys.size()) <= kMaxSamplesPerClip;
    if (samples.complete) samples.times = std::move(keys);
    const int uniform = static_cast<int>(std::min(wanted, kMaxSamplesPerClip));
    for (int i = 0; i < uniform; ++i)
        samples.times.push_back(clip.duration * static_cast<float>(i) / static_cast<float>(uniform));
    std::sort(samples.times.begin(), samples.times.end());
    samples.times.erase(std::unique(samples.times.begin(), samples.times.end()), samples.times.end());
    return samples;
}

// The model's vertices that differ in position or skin. Copies split only for normals, materials or
// texture coordinates skin to the same place (the Fox has 290 distinct of 1,728).
model::SkinnedModel distinctPositions(const model::SkinnedModel& model, std::uint32_t carried) {
    // Position, joints and weights as bits: equal bits skin equally.
    using Key = std::array<std::uint32_t, 12>;
    std::set<Key> seen;
    model::SkinnedModel distinct;
    for (const gpu::SkinVertex& v : model.vertices) {
        // A rare prop (the soldier's flag) would grow every character's sphere, which sizes levels of
        // detail and impostor cells too: it is left out (docs/props.md).
        if (model::onPropLeftOut(model, v, carried)) continue;
        Key key;
        std::memcpy(key.data(), &v.position, 16);
        std::memcpy(key.data() + 4, &v.joints, 32);
        if (seen.insert(key).second) distinct.vertices.push_back(v);
    }
    return distinct;
}

// The distinct vertices skinned in one pose: `clip` at `time`, or the rest pose without one.
std::vector<skin::CpuSkinnedVertex> skinPose(const model::SkinnedModel& model, const model::SkinnedModel& distinct,
                                             const anim::Clip* clip, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.restPose);
    if (clip) anim::sampleClip(*clip, time, skeleton.restPose, locals);
    std::vector<glm::mat4> modelSpace(skeleton.jointCount());
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    std::vector<gpu::BoneRows> bones(skeleton.jointCount());
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, glm::mat4(1.0f), bones);
    return skin::skinOnCpu(distinct, bones);
}

// Calls `visit` with every skinned point of every sampled pose, one pose at a time, so memory stays
// that of one pose however many are sampled.
template <typename Visit>
void forEachSampledPoint(const model::SkinnedModel& model, const model::SkinnedModel& distinct, Visit visit) {
    // The rest pose is what a character without a clip shows. (The bind pose itself is never drawn:
    // every method skins.)
    for (const skin::CpuSkinnedVertex& v : skinPose(model, distinct, nullptr, 0.0f)) visit(v.position);
    for (const anim::Clip& clip : model.clips)
        for (float time : sampleTimes(clip).times)
            for (const skin::CpuSkinnedVertex& v : skinPose(model, distinct, &clip, time)) visit(v.position);
}

// The smallest sphere holding spheres a and b (xyz centre, w radius).
glm::dvec4 enclose(const glm::dvec4& a, const glm::dvec4& b) {
    const double apart = glm::length(glm::dvec3(b) - glm::dvec3(a));
    if (apart + b.w <= a.w) return a;
    if (apart + a.w <= b.w) return b;
    const double radius = 0.5 * (apart + a.w + b.w);
    const glm::dvec3 centre = glm::dvec3(a) + (radius - a.w) / apart * (glm::dvec3(b) - glm::dvec3(a));
    return glm::dvec4(centre, radius);
}

// For clips sampled thinly: the ball about the origin that anim::poseReach bounds their poses by.
glm::dvec4 unsampledPoses(const model::SkinnedModel& model) {
    double bindDistance = 0.0;
    for (const gpu::SkinVertex& v : model.vertices) bindDistance = std::max(bindDistance, glm::length(glm::dvec3(v.position)));
    double reach = 0.0;
    for (const anim::Clip& clip : model.clips)
        if (!sampleTimes(clip).complete)
            reach = std::max(reach, anim::poseReach(model.skeleton, clip, bindDistance, INFINITY).distance);
    return glm::dvec4(0.0, 0.0, 0.0, reach);
}

}  // namespace

glm::vec4 computePoseSphere(const model::SkinnedModel& model) {
    if (model.vertices.empty()) return glm::vec4(0.0f);
    const model::SkinnedModel distinct = distinctPositions(model, model::propsMostCarry(model));
    // Two passes over the poses (the box, then the farthest point from its centre) instead of keeping
    // every pose's points: poses x vertices would be hundreds of megabytes for a long clip.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    forEachSampledPoint(model, distinct, [&](const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); });
    const glm::dvec3 center = 0.5 * (lo + hi);
    double radius = 0.0;
    forEachSampledPoint(model, distinct, [&](const glm::dvec3& p) { radius = std::max(radius, glm::length(p - center)); });
    glm::dvec4 sphere(center, radius * (1.0 + kMargin));
    if (const glm::dvec4 unsampled = unsampledPoses(model); unsampled.w > 0.0) sphere = enclose(sphere, unsampled);
    return glm::vec4(sphere);
}

float poseRadiusAbout(const model::SkinnedModel& model, const glm::vec3& centre, std::uint32_t carried) {
    if (model.vertices.empty()) return 0.0f;
    const model::SkinnedModel distinct = distinctPositions(model, carried);
    const glm::dvec3 c(centre);
    double radius = 0.0;
    forEachSampledPoint(model, distinct, [&](const glm::dvec3& p) { radius = std::max(radius, glm::length(p - c)); });
    radius *= 1.0 + kMargin;
    // Thinly sampled clips: the ball about the origin that bounds their poses, seen from the centre.
    if (const glm::dvec4 unsampled = unsampledPoses(model); unsampled.w > 0.0)
        radius = std::max(radius, glm::length(c) + unsampled.w);
    return static_cast<float>(radius);
}

}  // namespace crowd
