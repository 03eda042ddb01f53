#pragma once
// What both samplers (anim/sample_clip.h over a clip's channels, anim/sampling_job.h over the flat
// library) share once they have found the keys around a time: the span and glTF's cubic spline.
#include <cstdint>

#include <glm/glm.hpp>

namespace anim {

struct KeySpan {
    std::uint32_t key;  // at or before the time (clamped to the ends)
    float blend;        // towards the next key
    float interval;     // seconds between the two keys
};

// Hermite spline between keys k and k+1 as glTF defines CUBICSPLINE: `values` holds three per key
// (in-tangent, value, out-tangent).
inline glm::vec4 cubicSpline(const glm::vec4* values, const KeySpan& span) {
    const float s = span.blend, s2 = s * s, s3 = s2 * s;
    const glm::vec4 p0 = values[span.key * 3 + 1];
    const glm::vec4 m0 = values[span.key * 3 + 2] * span.interval;
    const glm::vec4 p1 = values[(span.key + 1) * 3 + 1];
    const glm::vec4 m1 = values[(span.key + 1) * 3 + 0] * span.interval;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

}  // namespace anim
