#include "model/footsteps.h"

#include <algorithm>
#include <cmath>

#include "gpu/error.h"
#include "model/clip_skinning.h"
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
// lift before it can touch down again: the hysteresis that makes a foot meeting the ground twice in
// one stance (the soldier's walk re-armed at 5 % of the lift; a galloping hind hoof that bobs up 8 cm)
// one touchdown.
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

// The given vertices skinned by `matrices`, in model space (the clip in place).
std::vector<glm::vec3> skinVertices(const SkinnedModel& model, const std::vector<glm::mat4>& matrices,
                                    const std::vector<std::uint32_t>& vertices) {
    std::vector<glm::vec3> out;
    out.reserve(vertices.size());
    for (std::uint32_t i : vertices) {
        const gpu::SkinVertex& v = model.vertices[i];
        glm::vec4 p(0.0f);
        for (int k = 0; k < 4; ++k) p += v.weights[k] * (matrices[v.joints[k]] * v.position);
        out.emplace_back(p);
    }
    return out;
}

// One foot over a cycle sampled at `steps` evenly spaced poses: per pose its lowest vertex's height
// and that vertex's speed over the ground.
struct FootTrack {
    std::vector<float> height, speed;
};

// poses[i][k]: the foot's vertex k at step i in model space. The ground moves under the clip by its
// root motion, so a vertex's place over the ground is its model-space place plus the root motion
// at that phase (whole strides added past the cycle's end).
FootTrack trackFoot(const std::vector<std::vector<glm::vec3>>& poses, const anim::RootMotion& root, float dt) {
    const int steps = static_cast<int>(poses.size());
    auto overGround = [&](int i, std::size_t k) {
        const int wrapped = ((i % steps) + steps) % steps;
        const float phase = static_cast<float>(i) / static_cast<float>(steps);
        const glm::vec2 carried = root.at(phase);  // whole cycles add whole strides
        return poses[static_cast<std::size_t>(wrapped)][k] + glm::vec3(carried.x, 0.0f, carried.y);
    };
    FootTrack track{std::vector<float>(poses.size()), std::vector<float>(poses.size())};
    for (int i = 0; i < steps; ++i) {
        const std::vector<glm::vec3>& pose = poses[static_cast<std::size_t>(i)];
        const std::size_t lowest = static_cast<std::size_t>(
            std::min_element(pose.begin(), pose.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; }) -
            pose.begin());
        const glm::vec3 d = overGround(i + 1, lowest) - overGround(i - 1, lowest);
        track.height[static_cast<std::size_t>(i)] = pose[lowest].y;
        track.speed[static_cast<std::size_t>(i)] = std::hypot(d.x, d.z) / (2.0f * dt);
    }
    return track;
}

// The steps (indices) at which a tracked foot touches down, going once round the cycle from its
// highest moment (in the air).
std::vector<int> touchdownSteps(const FootTrack& track, float downBand, float stopped) {
    const int steps = static_cast<int>(track.height.size());
    const float ground = *std::min_element(track.height.begin(), track.height.end());
    const auto highest = std::max_element(track.height.begin(), track.height.end());
    const float lift = *highest - ground;
    std::vector<int> result;
    bool up = true;
    for (int n = 0, start = static_cast<int>(highest - track.height.begin()); n < steps; ++n) {
        const int i = (start + n) % steps;
        const float above = track.height[static_cast<std::size_t>(i)] - ground;
        if (up && above <= downBand && track.speed[static_cast<std::size_t>(i)] <= stopped) {
            result.push_back(i);
            up = false;
        } else if (!up && above > kUpFraction * lift) {
            up = true;
        }
    }
    return result;
}

// How far a foot's lowest vertex rises over the cycle.
float liftOf(const std::vector<std::vector<glm::vec3>>& poses) {
    float lowest = 1e30f, highest = -1e30f;
    for (const std::vector<glm::vec3>& pose : poses) {
        float y = 1e30f;
        for (const glm::vec3& p : pose) y = std::min(y, p.y);
        lowest = std::min(lowest, y), highest = std::max(highest, y);
    }
    return highest - lowest;
}

}  // namespace

std::vector<anim::ClipEvent> findFootsteps(const SkinnedModel& model, const anim::Clip& clip,
                                           const std::vector<std::uint32_t>& feet) {
    std::vector<anim::ClipEvent> events;
    if (!(clip.duration > 0.0f)) return events;
    const int steps = std::max(kMinSteps, static_cast<int>(std::ceil(clip.duration / kLongestStep)));
    const float dt = clip.duration / static_cast<float>(steps);
    const float height = model.height();
    // Each foot's vertices at every step, in model space: heights do not depend on root motion, so
    // feet that never lift (idle) are known before it is measured.
    std::vector<std::vector<glm::mat4>> matrices(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps; ++i) matrices[static_cast<std::size_t>(i)] = clipSkinningMatrices(model, clip, dt * static_cast<float>(i));
    std::vector<std::vector<std::vector<glm::vec3>>> footPoses;
    std::vector<std::uint32_t> lifting;
    for (std::uint32_t foot : feet) {
        const std::vector<std::uint32_t> vertices = footVertices(model, foot);
        if (vertices.empty()) continue;
        std::vector<std::vector<glm::vec3>> poses(static_cast<std::size_t>(steps));
        for (std::size_t i = 0; i < poses.size(); ++i) poses[i] = skinVertices(model, matrices[i], vertices);
        if (liftOf(poses) <= kLeastLift * height) continue;  // never lifted: no steps
        footPoses.push_back(std::move(poses));
        lifting.push_back(foot);
    }
    if (lifting.empty()) return events;
    const anim::RootMotion root = measureRootMotion(model, clip);
    const float bodySpeed = glm::length(root.stride) / clip.duration;
    const float stopped = bodySpeed > 0.0f ? kStoppedFraction * bodySpeed : kStoppedInPlace * height;
    for (std::size_t f = 0; f < lifting.size(); ++f)
        for (int i : touchdownSteps(trackFoot(footPoses[f], root, dt), kDownBand * height, stopped))
            events.push_back({kFootstepEvent, dt * static_cast<float>(i), static_cast<std::int32_t>(lifting[f])});
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
