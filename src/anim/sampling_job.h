#pragma once
// Sampling job (ozz's SamplingJob over the flat library): one clip of one model at a time gives every
// joint's local transform. Each track remembers, in a caller-owned cursor, the key span it used last:
// time mostly moves forward by less than a key, so the next sample finds its span in one or two
// comparisons instead of a binary search. A cursor is only a hint; any value gives the same pose.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>

#include "anim/clip_library.h"
#include "anim/keyframes.h"
#include "anim/transform.h"

namespace anim {

struct SamplingJob {
    const ClipLibrary* library = nullptr;
    std::uint32_t model = 0;
    std::uint32_t clip = 0;  // the model's own clip index
    float time = 0.0f;       // seconds; wrapped into the clip, so clips loop
    // Three per joint (translation, rotation, scale), kept by the caller between frames.
    std::span<std::uint16_t> cursors;
    std::span<Transform> output;  // one per joint of the model

    // True when the spans fit the model and the clip exists.
    bool validate() const;
    // Writes every joint's local transform: keyed paths sampled as glTF defines their interpolation
    // (rotations along the shorter arc, normalized), the others at their rest value. Allocates nothing.
    void run() const;
};

// Spherical interpolation of unit quaternions (x, y, z, w) along the shorter arc, normalized, as
// shaders/animation.glsl.inc repeats it. Keys closer than 11.5 degrees of rotation (the quaternions'
// dot product above kNlerpAbove), as in densely keyed clips, take the normalized lerp instead: within
// 1.5e-4 rad of the arc there, and no inverse cosine and two sines for every joint of every character.
inline constexpr float kNlerpAbove = 0.995f;
glm::vec4 slerpShortest(glm::vec4 a, glm::vec4 b, float s);

// The job's steps for one track, shared with the SoA job (anim/soa_sampling_job.h).
// The key span holding t: first the cursor's span and the one after it, then a binary search (inline:
// both jobs call it for every keyed track of every character).
inline KeySpan findKeysFromCursor(const float* times, std::uint32_t count, float t, std::uint16_t& cursor) {
    // !(t > first): a NaN time holds the first key too, rather than searching past the last.
    if (count < 2 || !(t > times[0])) return {0, 0.0f, 0.0f};
    if (t >= times[count - 1]) return {count - 1, 0.0f, 0.0f};
    std::uint32_t key = std::min<std::uint32_t>(cursor, count - 2);
    if (!(times[key] <= t && t < times[key + 1])) {
        if (key + 2 < count && times[key + 1] <= t && t < times[key + 2]) {
            ++key;
        } else {
            key = static_cast<std::uint32_t>(std::upper_bound(times, times + count, t) - times) - 1;
        }
    }
    cursor = static_cast<std::uint16_t>(std::min<std::uint32_t>(key, std::numeric_limits<std::uint16_t>::max()));
    const float interval = times[key + 1] - times[key];
    return {key, (t - times[key]) / interval, interval};
}

// A keyed track's value at t as glTF's interpolation defines it (rotations not yet normalized).
glm::vec4 sampleTrack(const ClipLibrary& library, const gpu::AnimationTrack& track, bool rotation, float t,
                      std::uint16_t& cursor);

}  // namespace anim
