#include "anim/sample_clip.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "anim/keyframes.h"

namespace anim {
namespace {

// Index of the key at or before t (clamped), and the blend factor towards the next key.
KeySpan findKeys(const std::vector<float>& times, float t) {
    if (times.size() < 2 || t <= times.front()) return {0, 0.0f, 0.0f};
    if (t >= times.back()) return {static_cast<std::uint32_t>(times.size() - 1), 0.0f, 0.0f};
    const auto next = std::upper_bound(times.begin(), times.end(), t);
    const auto key = static_cast<std::uint32_t>(next - times.begin()) - 1;
    const float interval = times[key + 1] - times[key];
    return {key, (t - times[key]) / interval, interval};
}

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

glm::vec4 slerpShortest(const glm::vec4& a, const glm::vec4& b, float s) {
    glm::quat qa = toQuat(a), qb = toQuat(b);
    if (glm::dot(qa, qb) < 0.0f) qb = -qb;
    const glm::quat q = glm::normalize(glm::slerp(qa, qb, s));
    return {q.x, q.y, q.z, q.w};
}

glm::vec4 sampleChannel(const Channel& channel, float t) {
    const KeySpan span = findKeys(channel.times, t);
    const bool lastKey = span.key + 1 >= channel.times.size();
    switch (channel.interpolation) {
        case Interpolation::CubicSpline: {
            if (lastKey || span.blend == 0.0f) return channel.values[span.key * 3 + 1];
            const glm::vec4 value = cubicSpline(channel.values.data(), span);
            if (channel.path != ChannelPath::Rotation) return value;
            // Between opposite keys (q and -q, one rotation) the spline can pass through zero, which
            // has no direction: there the rotation follows the short arc between the keys instead.
            const float length = glm::length(value);
            if (length > 1e-6f) return value / length;
            return slerpShortest(glm::normalize(channel.values[span.key * 3 + 1]),
                                 glm::normalize(channel.values[(span.key + 1) * 3 + 1]), span.blend);
        }
        case Interpolation::Step:
            return channel.values[span.key];
        case Interpolation::Linear:
            break;
    }
    if (lastKey || span.blend == 0.0f) return channel.values[span.key];
    const glm::vec4& a = channel.values[span.key];
    const glm::vec4& b = channel.values[span.key + 1];
    if (channel.path == ChannelPath::Rotation) return slerpShortest(a, b, span.blend);
    return glm::mix(a, b, span.blend);
}

}  // namespace

float wrapTime(float time, float duration) {
    if (!(duration > 0.0f)) return 0.0f;
    float t = std::fmod(time, duration);
    if (t < 0.0f) t += duration;
    return t >= duration ? 0.0f : t;
}

void sampleClip(const Clip& clip, float time, std::span<const Transform> rest, std::span<Transform> out) {
    assert(out.size() == rest.size());
    std::copy(rest.begin(), rest.end(), out.begin());
    const float t = wrapTime(time, clip.duration);
    for (const Channel& channel : clip.channels) {
        if (channel.joint >= out.size() || channel.times.empty()) continue;
        const glm::vec4 value = sampleChannel(channel, t);
        Transform& joint = out[channel.joint];
        switch (channel.path) {
            case ChannelPath::Translation: joint.translation = glm::vec3(value); break;
            case ChannelPath::Rotation: joint.rotation = glm::normalize(toQuat(value)); break;
            case ChannelPath::Scale: joint.scale = glm::vec3(value); break;
        }
    }
}

}  // namespace anim
