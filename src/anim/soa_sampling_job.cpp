#include "anim/soa_sampling_job.h"

#include "anim/sample_clip.h"
#include "anim/sampling_job.h"
#include "anim/soa_maths.h"

namespace anim {
namespace {

// One lane's keys around the time: values a and b and the blend s towards b. A held value (the rest
// value, a STEP key, a time on a key or past the last, a cubic spline's value) comes as a = b, s = 0:
// the scalar job returns it as it is, and so does the lerp; the slerp is skipped for such lanes.
struct KeyPair {
    glm::vec4 a, b;
    float s;
};

// Cubic splines: the scalar job's own code (out of line: rare).
[[gnu::noinline]] void cubicKeyPair(const ClipLibrary& library, const gpu::AnimationTrack& track, bool rotation, float t,
                                    std::uint16_t& cursor, KeyPair& out) {
    const glm::vec4 value = sampleTrack(library, track, rotation, t, cursor);
    out = {value, value, 0.0f};
}

inline void keyPair(const ClipLibrary& library, const gpu::AnimationTrack& track, bool rotation, float t,
                    std::uint16_t& cursor, const glm::vec4& rest, KeyPair& out) {
    if (track.keyCount == 0) {
        out = {rest, rest, 0.0f};
        return;
    }
    if (track.interpolation == 2u) return cubicKeyPair(library, track, rotation, t, cursor, out);
    const KeySpan span = findKeysFromCursor(library.keyTimes().data() + track.firstKey, track.keyCount, t, cursor);
    const glm::vec4* values = library.keyValues().data() + track.firstValue;
    if (track.interpolation == 0u || span.key + 1 >= track.keyCount || span.blend == 0.0f)
        out = {values[span.key], values[span.key], 0.0f};
    else
        out = {values[span.key], values[span.key + 1], span.blend};
}

// The four lanes' a (or b) values turned into structure of arrays.
template <class F>
soa::Quat<F> lanes(const KeyPair (&keys)[kSoaLanes], glm::vec4 KeyPair::*value) {
    F x = F::load(&(keys[0].*value).x), y = F::load(&(keys[1].*value).x), z = F::load(&(keys[2].*value).x),
      w = F::load(&(keys[3].*value).x);
    transpose(x, y, z, w);
    return {x, y, z, w};
}

template <class F>
F blends(const KeyPair (&keys)[kSoaLanes]) { return F::set(keys[0].s, keys[1].s, keys[2].s, keys[3].s); }

// Translation or scale: glm::mix of the keys' xyz. Four held lanes (most groups: few joints have
// keyed translations, and scales fewer) keep their values as they are, as the scalar job does.
template <class F>
CROWD_SIMD_INLINE void lerpLanes(const KeyPair (&keys)[kSoaLanes], SoaFloat3& out) {
    const soa::Quat<F> a = lanes<F>(keys, &KeyPair::a);
    const F s = blends<F>(keys);
    if ((s == F::splat(0.0f)).all()) return soa::store(soa::Vec3<F>{a.x, a.y, a.z}, out);
    const soa::Quat<F> b = lanes<F>(keys, &KeyPair::b);
    soa::store(soa::mix(soa::Vec3<F>{a.x, a.y, a.z}, soa::Vec3<F>{b.x, b.y, b.z}, s), out);
}

// Rotation: slerp where the lane blends, then normalized as a glm::quat (the scalar job's toQuat).
template <class F>
CROWD_SIMD_INLINE void slerpLanes(const KeyPair (&keys)[kSoaLanes], SoaQuat& out) {
    soa::Quat<F> q = lanes<F>(keys, &KeyPair::a);
    const F s = blends<F>(keys);
    const typename F::Mask held = s == F::splat(0.0f);
    if (!held.all()) q = soa::select<F>(held, q, soa::slerpShortest(q, lanes<F>(keys, &KeyPair::b), s));
    soa::store(soa::normalizeWxyz(q), out);
}

}  // namespace

bool SoaSamplingJob::validate() const {
    if (!library || model >= library->modelCount() || clip >= library->clipCount(model)) return false;
    const std::uint32_t joints = library->jointCount(model);
    return output.size() >= soaGroups(joints) && cursors.size() >= 3u * joints;
}

template <class F>
void SoaSamplingJob::runWith() const {
    const gpu::AnimationModel& m = library->models()[model];
    const gpu::AnimationClip& c = library->clip(model, clip);
    const float t = wrapTime(time, c.timing.x);
    const std::uint32_t joints = m.info.y;
    const gpu::AnimationJoint* rest = library->joints().data() + m.info.x;
    const gpu::AnimationTrack* tracks = library->tracks().data() + c.info.x;
    const glm::vec4 identity[3] = {glm::vec4(0.0f), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), glm::vec4(1.0f, 1.0f, 1.0f, 0.0f)};
    for (std::uint32_t g = 0; g < soaGroups(joints); ++g) {
        KeyPair translation[kSoaLanes], rotation[kSoaLanes], scale[kSoaLanes];
        for (std::uint32_t lane = 0; lane < kSoaLanes; ++lane) {
            const std::uint32_t j = g * kSoaLanes + lane;
            if (j >= joints) {
                translation[lane] = {identity[0], identity[0], 0.0f};
                rotation[lane] = {identity[1], identity[1], 0.0f};
                scale[lane] = {identity[2], identity[2], 0.0f};
                continue;
            }
            const gpu::AnimationTrack* track = tracks + 3u * j;
            std::uint16_t* cursor = cursors.data() + 3u * j;
            keyPair(*library, track[0], false, t, cursor[0], rest[j].restTranslation, translation[lane]);
            keyPair(*library, track[1], true, t, cursor[1], rest[j].restRotation, rotation[lane]);
            keyPair(*library, track[2], false, t, cursor[2], rest[j].restScale, scale[lane]);
        }
        lerpLanes<F>(translation, output[g].translation);
        slerpLanes<F>(rotation, output[g].rotation);
        lerpLanes<F>(scale, output[g].scale);
    }
}

void SoaSamplingJob::run() const { runWith<simd::NativeFloat4>(); }

template void SoaSamplingJob::runWith<simd::LaneFloat4>() const;
#ifdef CROWD_ANIM_HAVE_SSE2
template void SoaSamplingJob::runWith<simd::Sse2Float4>() const;
#endif

}  // namespace anim
