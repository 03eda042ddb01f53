#include "model/looping_clip.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "anim/local_to_model.h"

namespace model {
namespace {

// Keys this close to the rest value count as not animated, so still joints get no channel.
constexpr float kStillTolerance = 1e-6f;

glm::vec4 asKey(const glm::quat& q) { return {q.x, q.y, q.z, q.w}; }

bool moves(const std::vector<glm::vec4>& keys, const glm::vec4& rest) {
    for (const glm::vec4& key : keys)
        if (glm::any(glm::greaterThan(glm::abs(key - rest), glm::vec4(kStillTolerance)))) return true;
    return false;
}

void addChannel(anim::Clip& clip, std::uint32_t joint, anim::ChannelPath path, const std::vector<float>& times,
                std::vector<glm::vec4> keys) {
    anim::Channel channel;
    channel.joint = joint;
    channel.path = path;
    channel.interpolation = anim::Interpolation::Linear;
    channel.times = times;
    channel.values = std::move(keys);
    clip.channels.push_back(std::move(channel));
}

}  // namespace

anim::Clip bakeLoopingClip(std::string name, float duration, int keyIntervals, const anim::Skeleton& skeleton,
                           const PoseAtPhase& pose) {
    const std::size_t joints = skeleton.jointCount(), keyCount = static_cast<std::size_t>(keyIntervals) + 1;
    std::vector<float> times(keyCount);
    std::vector<std::vector<glm::vec4>> rotations(joints), translations(joints);
    std::vector<anim::Transform> locals(joints);
    for (std::size_t k = 0; k < keyCount; ++k) {
        times[k] = duration * static_cast<float>(k) / static_cast<float>(keyIntervals);
        if (k + 1 == keyCount) {
            // The closing key repeats the first exactly: a seamless loop, bit for bit.
            for (std::size_t j = 0; j < joints; ++j) {
                rotations[j].push_back(rotations[j].front());
                translations[j].push_back(translations[j].front());
            }
            break;
        }
        locals = skeleton.restPose;
        pose(static_cast<float>(k) / static_cast<float>(keyIntervals), locals);
        for (std::size_t j = 0; j < joints; ++j) {
            glm::quat q = glm::normalize(locals[j].rotation);
            // Keep neighbouring keys in the same hemisphere so the curve has no sign jumps.
            if (k > 0 && glm::dot(asKey(q), rotations[j].back()) < 0.0f) q = -q;
            rotations[j].push_back(asKey(q));
            translations[j].push_back(glm::vec4(locals[j].translation, 0.0f));
        }
    }
    anim::Clip clip;
    clip.name = std::move(name);
    clip.duration = duration;
    for (std::size_t j = 0; j < joints; ++j) {
        const anim::Transform& rest = skeleton.restPose[j];
        const auto joint = static_cast<std::uint32_t>(j);
        if (moves(translations[j], glm::vec4(rest.translation, 0.0f)))
            addChannel(clip, joint, anim::ChannelPath::Translation, times, std::move(translations[j]));
        if (moves(rotations[j], asKey(rest.rotation)) && moves(rotations[j], -asKey(rest.rotation)))
            addChannel(clip, joint, anim::ChannelPath::Rotation, times, std::move(rotations[j]));
    }
    return clip;
}

float lowestSkinnedY(const SkinnedModel& model, std::span<const anim::Transform> pose) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<glm::mat4> global(skeleton.jointCount());
    anim::localToModel(skeleton.parents, pose, skeleton.rootTransform, global);
    // Only the y row of each skinning matrix matters here.
    std::vector<glm::vec4> yRows(global.size());
    for (std::size_t j = 0; j < global.size(); ++j) {
        const glm::mat4 skin = global[j] * skeleton.inverseBind[j];
        yRows[j] = {skin[0][1], skin[1][1], skin[2][1], skin[3][1]};
    }
    float lowest = std::numeric_limits<float>::max();
    for (const gpu::SkinVertex& v : model.vertices) {
        float y = 0.0f;
        for (int k = 0; k < 4; ++k) y += v.weights[k] * glm::dot(yRows[v.joints[k]], v.position);
        lowest = std::min(lowest, y);
    }
    return lowest;
}

glm::quat swing(float degrees) { return glm::angleAxis(glm::radians(-degrees), glm::vec3(1, 0, 0)); }
glm::quat lean(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(1, 0, 0)); }
glm::quat bank(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1)); }
glm::quat turn(float degrees) { return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 1, 0)); }

float wave(float phase, float cycles, float offset) {
    return std::sin(2.0f * std::numbers::pi_v<float> * (phase * cycles + offset));
}

float bump(float phase, float center, float width) {
    float d = std::fabs(wrapPhase(phase) - wrapPhase(center));
    d = std::min(d, 1.0f - d);
    return std::exp(-(d / width) * (d / width));
}

float wrapPhase(float phase) { return phase - std::floor(phase); }

std::uint32_t findJoint(const anim::Skeleton& skeleton, const std::string& name) {
    const auto it = std::find(skeleton.jointNames.begin(), skeleton.jointNames.end(), name);
    assert(it != skeleton.jointNames.end());
    return static_cast<std::uint32_t>(it - skeleton.jointNames.begin());
}

}  // namespace model
