#include "model/footsteps.h"

#include <algorithm>
#include <cmath>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "gpu/error.h"
#include "model/measure_root_motion.h"

namespace model {
namespace {

// Poses a cycle is sampled at: at least this many, and no further apart than kLongestStep, so a
// touchdown lands well within a 60 Hz frame of where the mesh puts it.
constexpr int kMinSteps = 256;
constexpr float kLongestStep = 0.002f;  // seconds
// Touchdown: the foot's lowest vertex within kDownBand of the lowest it gets over the cycle (a
// fraction of the model's height: 9 mm on the soldier) and moving over the ground at under
// kStoppedFraction of the body's mean speed. A foot must then rise past kUpFraction of its highest
// lift before it can touch down again: the hysteresis that keeps a heel strike and the toes coming
// down after it, or a hoof that bobs under a rocking gallop, one touchdown.
constexpr float kDownBand = 0.005f;
constexpr float kStoppedFraction = 0.1f;
constexpr float kStoppedInPlace = 0.005f;  // model heights per second, for clips that do not travel
constexpr float kUpFraction = 0.5f;
// A foot that never lifts more than this (a fraction of the model's height) takes no steps (idle).
constexpr float kLeastLift = 0.03f;

// A foot's vertices: those skinned at least half to the foot joint or a joint under it.
std::vector<std::uint32_t> footVertices(const SkinnedModel& model, std::uint32_t foot) {
    const anim::Skeleton& s = model.skeleton;
    std::vector<bool> inFoot(s.jointCount(), false);
    inFoot[foot] = true;
    for (std::size_t j = foot + 1; j < s.jointCount(); ++j)  // parents come before their children
        inFoot[j] = s.parents[j] >= 0 && inFoot[static_cast<std::size_t>(s.parents[j])];
    std::vector<std::uint32_t> result;
    for (std::size_t v = 0; v < model.vertices.size(); ++v) {
        const gpu::SkinVertex& vertex = model.vertices[v];
        float weight = 0.0f;
        for (int k = 0; k < 4; ++k)
            if (inFoot[vertex.joints[k]]) weight += vertex.weights[k];
        if (weight >= 0.5f) result.push_back(static_cast<std::uint32_t>(v));
    }
    return result;
}

// The given vertices skinned at `time` into the clip and carried by its root motion: where they are
// over the ground the character walks on.
std::vector<glm::vec3> groundPositions(const SkinnedModel& model, const anim::Clip& clip, const anim::RootMotion& root,
                                       const std::vector<std::uint32_t>& vertices, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.jointCount());
    std::vector<glm::mat4> global(skeleton.jointCount());
    anim::sampleClip(clip, time, skeleton.restPose, locals);
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, global);
    for (std::size_t j = 0; j < global.size(); ++j) global[j] = global[j] * skeleton.inverseBind[j];
    const glm::vec2 carried = root.at(time / clip.duration);
    std::vector<glm::vec3> positions;
    positions.reserve(vertices.size());
    for (std::uint32_t i : vertices) {
        const gpu::SkinVertex& v = model.vertices[i];
        glm::vec4 p(0.0f);
        for (int k = 0; k < 4; ++k) p += v.weights[k] * (global[v.joints[k]] * v.position);
        positions.emplace_back(p.x + carried.x, p.y, p.z + carried.y);
    }
    return positions;
}

// One foot over the sampled cycle: its lowest vertex's height and that vertex's speed over the ground.
struct FootTrack {
    std::vector<float> height, speed;
};

}  // namespace

std::vector<anim::ClipEvent> findFootsteps(const SkinnedModel& model, const anim::Clip& clip,
                                           const std::vector<std::uint32_t>& feet) {
    std::vector<anim::ClipEvent> events;
    if (!(clip.duration > 0.0f) || feet.empty()) return events;
    const int steps = std::max(kMinSteps, static_cast<int>(std::ceil(clip.duration / kLongestStep)));
    const float dt = clip.duration / static_cast<float>(steps);
    const anim::RootMotion root = measureRootMotion(model, clip);
    const float height = model.height();
    const float bodySpeed = glm::length(root.stride) / clip.duration;
    const float stopped = bodySpeed > 0.0f ? kStoppedFraction * bodySpeed : kStoppedInPlace * height;

    std::vector<std::vector<std::uint32_t>> footSets;
    std::vector<std::uint32_t> all;
    for (std::uint32_t foot : feet) {
        footSets.push_back(footVertices(model, foot));
        all.insert(all.end(), footSets.back().begin(), footSets.back().end());
    }
    // Ground positions of every foot vertex at every step (the last step wraps to the first).
    std::vector<std::vector<glm::vec3>> poses(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps; ++i) poses[static_cast<std::size_t>(i)] = groundPositions(model, clip, root, all, dt * static_cast<float>(i));
    const glm::vec2 stride = root.stride;
    auto at = [&](int i, std::size_t k) {
        // Past the cycle's end the ground positions carry on by whole strides.
        const int wrapped = ((i % steps) + steps) % steps;
        const float cycles = static_cast<float>((i - wrapped) / steps);
        const glm::vec3 p = poses[static_cast<std::size_t>(wrapped)][k];
        return p + glm::vec3(stride.x, 0.0f, stride.y) * cycles;
    };

    std::size_t offset = 0;
    for (std::size_t f = 0; f < feet.size(); ++f) {
        const std::size_t count = footSets[f].size();
        if (count == 0) continue;
        FootTrack track{std::vector<float>(static_cast<std::size_t>(steps)), std::vector<float>(static_cast<std::size_t>(steps))};
        for (int i = 0; i < steps; ++i) {
            std::size_t lowest = offset;
            for (std::size_t k = offset; k < offset + count; ++k)
                if (at(i, k).y < at(i, lowest).y) lowest = k;
            const glm::vec3 d = at(i + 1, lowest) - at(i - 1, lowest);
            track.height[static_cast<std::size_t>(i)] = at(i, lowest).y;
            track.speed[static_cast<std::size_t>(i)] = std::hypot(d.x, d.z) / (2.0f * dt);
        }
        offset += count;
        const float ground = *std::min_element(track.height.begin(), track.height.end());
        const auto highest = std::max_element(track.height.begin(), track.height.end());
        const float lift = *highest - ground;
        if (lift <= kLeastLift * height) continue;  // never lifted: no steps
        // From the foot's highest moment (in the air), once round the cycle.
        const int start = static_cast<int>(highest - track.height.begin());
        bool up = true;
        for (int n = 0; n < steps; ++n) {
            const std::size_t i = static_cast<std::size_t>((start + n) % steps);
            const float above = track.height[i] - ground;
            if (up && above <= kDownBand * height && track.speed[i] <= stopped) {
                events.push_back({kFootstepEvent, dt * static_cast<float>(i), static_cast<std::int32_t>(feet[f])});
                up = false;
            } else if (!up && above > kUpFraction * lift) {
                up = true;
            }
        }
    }
    std::sort(events.begin(), events.end(), [](const anim::ClipEvent& a, const anim::ClipEvent& b) { return a.time < b.time; });
    return events;
}

void attachFootsteps(SkinnedModel& model, const std::vector<std::string>& footJoints) {
    std::vector<std::uint32_t> feet;
    for (const std::string& name : footJoints) {
        const auto found = std::find(model.skeleton.jointNames.begin(), model.skeleton.jointNames.end(), name);
        if (found == model.skeleton.jointNames.end()) throw gpu::Error(model.name + ": no foot joint '" + name + "'");
        feet.push_back(static_cast<std::uint32_t>(found - model.skeleton.jointNames.begin()));
    }
    for (anim::Clip& clip : model.clips) {
        std::vector<anim::ClipEvent> steps = findFootsteps(model, clip, feet);
        clip.events.insert(clip.events.end(), steps.begin(), steps.end());
        std::stable_sort(clip.events.begin(), clip.events.end(),
                         [](const anim::ClipEvent& a, const anim::ClipEvent& b) { return a.time < b.time; });
    }
}

}  // namespace model
