#include "anim/sampling_job.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "anim/keyframes.h"
#include "anim/sample_clip.h"

namespace anim {

glm::vec4 sampleTrack(const ClipLibrary& library, const gpu::AnimationTrack& track, bool rotation, float t,
                      std::uint16_t& cursor) {
    const KeySpan span = findKeysFromCursor(library.keyTimes().data() + track.firstKey, track.keyCount, t, cursor);
    const glm::vec4* values = library.keyValues().data() + track.firstValue;
    const bool lastKey = span.key + 1 >= track.keyCount;
    if (track.interpolation == 2u) {  // cubic spline
        if (lastKey || span.blend == 0.0f) return values[span.key * 3 + 1];
        const glm::vec4 value = cubicSpline(values, span);
        if (!rotation) return value;
        // Between opposite keys the spline can pass through zero: the short arc between them instead.
        const float length = glm::length(value);
        if (length > 1e-6f) return value / length;
        return slerpShortest(glm::normalize(values[span.key * 3 + 1]), glm::normalize(values[(span.key + 1) * 3 + 1]),
                             span.blend);
    }
    if (track.interpolation == 0u || lastKey || span.blend == 0.0f) return values[span.key];
    if (rotation) return slerpShortest(values[span.key], values[span.key + 1], span.blend);
    return glm::mix(values[span.key], values[span.key + 1], span.blend);
}

namespace {

glm::quat toQuat(const glm::vec4& v) { return glm::normalize(glm::quat(v.w, v.x, v.y, v.z)); }

}  // namespace

glm::vec4 slerpShortest(glm::vec4 a, glm::vec4 b, float s) {
    float cosTheta = glm::dot(a, b);
    if (cosTheta < 0.0f) b = -b, cosTheta = -cosTheta;
    glm::vec4 q;
    if (cosTheta > kNlerpAbove) {
        q = glm::mix(a, b, s);
    } else {
        const float angle = std::acos(cosTheta);
        q = (std::sin((1.0f - s) * angle) * a + std::sin(s * angle) * b) / std::sin(angle);
    }
    return glm::normalize(q);
}

bool SamplingJob::validate() const {
    if (!library || model >= library->modelCount() || clip >= library->clipCount(model)) return false;
    const std::uint32_t joints = library->jointCount(model);
    return output.size() == joints && cursors.size() >= 3u * joints;
}

void SamplingJob::run() const {
    const gpu::AnimationModel& m = library->models()[model];
    const gpu::AnimationClip& c = library->clip(model, clip);
    const float t = wrapTime(time, c.timing.x);
    for (std::uint32_t j = 0; j < m.info.y; ++j) {
        const gpu::AnimationJoint& rest = library->joints()[m.info.x + j];
        const gpu::AnimationTrack* tracks = library->tracks().data() + c.info.x + 3u * j;
        std::uint16_t* cursor = cursors.data() + 3u * j;
        Transform& out = output[j];
        out.translation = tracks[0].keyCount ? glm::vec3(sampleTrack(*library, tracks[0], false, t, cursor[0]))
                                             : glm::vec3(rest.restTranslation);
        out.rotation = toQuat(tracks[1].keyCount ? sampleTrack(*library, tracks[1], true, t, cursor[1]) : rest.restRotation);
        out.scale = tracks[2].keyCount ? glm::vec3(sampleTrack(*library, tracks[2], false, t, cursor[2]))
                                       : glm::vec3(rest.restScale);
    }
}

}  // namespace anim
