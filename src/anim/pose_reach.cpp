#include "anim/pose_reach.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace anim {
namespace {

double magnitude(const glm::vec4& v, ChannelPath path) {
    const glm::dvec4 d(v);
    switch (path) {
        case ChannelPath::Translation: return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        case ChannelPath::Rotation: return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + d.w * d.w);
        case ChannelPath::Scale: return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    }
    return 0.0;
}

// How much the upper 3x3 can lengthen a vector (its spectral norm): the square root of the largest
// eigenvalue of AᵀA, in closed form for a symmetric 3x3 (Smith, CACM 1961), with a margin for
// rounding, and never above the Frobenius norm (which bounds it too).
double linearNorm(const glm::mat4& m) {
    const glm::dmat3 a(m);
    const glm::dmat3 s = glm::transpose(a) * a;
    const double frobenius = std::sqrt(s[0][0] + s[1][1] + s[2][2]);
    const double offDiagonal = s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2];
    const double mean = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
    const double spread = (s[0][0] - mean) * (s[0][0] - mean) + (s[1][1] - mean) * (s[1][1] - mean) +
                          (s[2][2] - mean) * (s[2][2] - mean) + 2.0 * offDiagonal;
    if (!(spread > 0.0)) return std::min(frobenius, std::sqrt(std::max(mean, 0.0)) * (1.0 + 1e-9));
    const double p = std::sqrt(spread / 6.0);
    const double half = glm::determinant((s - mean * glm::dmat3(1.0)) / p) / 2.0;
    const double angle = std::acos(std::clamp(half, -1.0, 1.0)) / 3.0;
    const double largest = mean + 2.0 * p * std::cos(angle);
    return std::min(frobenius, std::sqrt(std::max(largest, 0.0)) * (1.0 + 1e-9));
}

double translationNorm(const glm::mat4& m) { return glm::length(glm::dvec3(m[3])); }

// Per joint: bounds on the local translation's length and the scale's largest component.
struct LocalBounds {
    std::vector<double> translation, scale;
};

LocalBounds restBounds(const Skeleton& skeleton) {
    LocalBounds bounds;
    for (const Transform& t : skeleton.restPose) {
        bounds.translation.push_back(glm::length(glm::dvec3(t.translation)));
        bounds.scale.push_back(std::max({std::abs(double(t.scale.x)), std::abs(double(t.scale.y)),
                                         std::abs(double(t.scale.z))}));
    }
    return bounds;
}

// The skinned-vertex bound for these local bounds: down the hierarchy, a joint's linear part grows by
// its scale (a rotation keeps lengths) and its origin moves by the parent's linear part times its
// translation; the bone matrix adds the inverse bind matrix. Weights sum to 1, so a vertex lies within
// the largest of its bones' reach. Infinite (or NaN from inf * 0) propagates as "beyond any limit".
double skinnedReach(const Skeleton& skeleton, const LocalBounds& local, double maxBindDistance) {
    const std::size_t joints = skeleton.jointCount();
    std::vector<double> linear(joints), origin(joints);
    const double rootLinear = linearNorm(skeleton.rootTransform), rootOrigin = translationNorm(skeleton.rootTransform);
    const double reachOf = std::max(1.0, maxBindDistance);
    double reach = 0.0;
    for (std::size_t j = 0; j < joints; ++j) {
        const std::int32_t parent = skeleton.parents[j];
        const double aboveLinear = parent < 0 ? rootLinear : linear[static_cast<std::size_t>(parent)];
        const double aboveOrigin = parent < 0 ? rootOrigin : origin[static_cast<std::size_t>(parent)];
        linear[j] = aboveLinear * local.scale[j];
        origin[j] = aboveOrigin + aboveLinear * local.translation[j];
        const glm::mat4& inverseBind = skeleton.inverseBind[j];
        const double boneLinear = linear[j] * linearNorm(inverseBind);
        const double boneOrigin = linear[j] * translationNorm(inverseBind) + origin[j];
        const double bone = boneLinear * reachOf + boneOrigin;
        if (!(bone <= reach)) reach = std::isnan(bone) ? INFINITY : bone;
    }
    return reach;
}

// The local bounds with the clip's first `count` channels applied over the rest pose. A rotation
// channel moves no lengths, but its unnormalized values must stay finite: its reach counts as a
// translation would, on no joint.
double reachWithChannels(const Skeleton& skeleton, const Clip& clip, std::span<const double> channelBounds,
                         std::size_t count, double maxBindDistance) {
    LocalBounds local = restBounds(skeleton);
    double rotations = 0.0;
    for (std::size_t c = 0; c < count; ++c) {
        const Channel& channel = clip.channels[c];
        if (channel.joint >= skeleton.jointCount()) continue;  // the sampler skips it too
        double& bound = channel.path == ChannelPath::Translation ? local.translation[channel.joint]
                        : channel.path == ChannelPath::Scale     ? local.scale[channel.joint]
                                                                 : rotations;
        if (!(channelBounds[c] <= bound)) bound = channelBounds[c];
    }
    return std::max(rotations, skinnedReach(skeleton, local, maxBindDistance));
}

}  // namespace

double channelReach(const Channel& channel) {
    const std::size_t keys = channel.times.size();
    if (keys == 0) return 0.0;
    if (channel.interpolation != Interpolation::CubicSpline) {
        double reach = 0.0;
        for (std::size_t k = 0; k < keys && k < channel.values.size(); ++k)
            reach = std::max(reach, magnitude(channel.values[k], channel.path));
        return reach;
    }
    // Values are (in-tangent, value, out-tangent) per key; between keys k and k+1 the sampler blends
    // value k and k+1 with weights in [0, 1] that sum to 1, and the tangents times the interval with
    // weights of at most 4/27.
    if (channel.values.size() < keys * 3) return INFINITY;
    const auto value = [&](std::size_t k, int part) { return magnitude(channel.values[k * 3 + part], channel.path); };
    double reach = value(0, 1);
    for (std::size_t k = 0; k + 1 < keys; ++k) {
        const double interval = static_cast<double>(channel.times[k + 1]) - static_cast<double>(channel.times[k]);
        const double span = std::max(value(k, 1), value(k + 1, 1)) + 4.0 / 27.0 * interval * (value(k, 2) + value(k + 1, 0));
        reach = std::max(reach, span);
    }
    return reach;
}

PoseReach poseReach(const Skeleton& skeleton, const Clip& clip, double maxBindDistance, double limit) {
    std::vector<double> channelBounds;
    channelBounds.reserve(clip.channels.size());
    for (const Channel& channel : clip.channels) channelBounds.push_back(channelReach(channel));
    PoseReach result;
    result.distance = reachWithChannels(skeleton, clip, channelBounds, clip.channels.size(), maxBindDistance);
    if (result.distance <= limit) return result;
    if (!(reachWithChannels(skeleton, clip, channelBounds, 0, maxBindDistance) <= limit)) return result;
    for (std::size_t c = 0; c < clip.channels.size(); ++c)
        if (!(reachWithChannels(skeleton, clip, channelBounds, c + 1, maxBindDistance) <= limit)) {
            result.channel = static_cast<int>(c);
            break;
        }
    return result;
}

}  // namespace anim
