#include "crowd/segment.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace crowd {
namespace {

float windowOf(const gpu::MotionRecord& m) { return std::max(m.timing.y, m.timing.w); }

double rateOf(const Segment& segment) { return segment.rate != 0.0 ? segment.rate : segment.motion.phase.z; }

// motionPhase in double, for an elapsed time past the crossfade.
double phaseAfterFade(const Segment& segment, double elapsed) {
    const gpu::MotionRecord& m = segment.motion;
    const double fade = m.timing.y, from = m.phase.y, to = rateOf(segment);
    if (fade <= 0.0) return m.phase.x + to * elapsed;
    return m.phase.x + 0.5 * (from + to) * fade + to * (elapsed - fade);
}

// Root motion of `clip` from phase `a` to phase `b`, however many cycles apart: the whole strides are
// counted in double, only the points within the cycle go through the float curve.
glm::vec2 rootBetween(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, double a, double b) {
    const double wholeA = std::floor(a), wholeB = std::floor(b);
    const glm::vec2 within = library.rootMotion(model, clip, static_cast<float>(b - wholeB)) -
                             library.rootMotion(model, clip, static_cast<float>(a - wholeA));
    return within + library.stride(model, clip) * static_cast<float>(wholeB - wholeA);
}

// The segment restated at `at`, past its curved part: straight and steady from there, its phase within
// one cycle, its position where the segment has carried it by then.
gpu::MotionRecord steadyFrom(const Segment& segment, double at, const anim::ClipLibrary& library, std::uint32_t model) {
    const gpu::MotionRecord& m = segment.motion;
    const float window = windowOf(m);
    const double phase = phaseAfterFade(segment, at - segment.start);
    const float heading = motionHeading(m, window);
    glm::vec3 position(m.origin);
    if (m.phase.w == MOTION_ROOT) {
        const glm::vec2 curvedEnd(std::bit_cast<float>(m.clips.z), std::bit_cast<float>(m.clips.w));
        const glm::vec2 straight = rootBetween(library, model, m.clips.y, motionPhase(m, window), phase);
        const glm::vec2 offset = curvedEnd + turnToWorld(straight, heading);
        position.x += offset.x;
        position.z += offset.y;
    }
    gpu::MotionRecord steady{};
    steady.origin = glm::vec4(position, heading);
    steady.phase = glm::vec4(static_cast<float>(phase - std::floor(phase)), m.phase.z, m.phase.z, m.phase.w);
    steady.clips = glm::uvec4(m.clips.y, m.clips.y, 0u, 0u);  // no curved part: it ends where it starts
    return steady;
}

}  // namespace

gpu::MotionRecord recordFrom(const Segment& segment, double epoch, const anim::ClipLibrary& library, std::uint32_t model) {
    if (epoch - segment.start > static_cast<double>(windowOf(segment.motion))) {
        return steadyFrom(segment, epoch, library, model);  // starts at the epoch: timing.x = 0
    }
    gpu::MotionRecord record = segment.motion;
    record.timing.x = static_cast<float>(segment.start - epoch);
    return record;
}

MotionState stateOf(const Segment& segment, double time, const anim::ClipLibrary& library, std::uint32_t model) {
    // Relative to an epoch at `time` itself, the record's float times are as small as they can be.
    return evaluateMotion(recordFrom(segment, time, library, model), 0.0f, library, model);
}

double unwrappedPhase(const Segment& segment, double time) {
    const double elapsed = std::max(time - segment.start, 0.0);
    if (elapsed <= segment.motion.timing.y) return motionPhase(segment.motion, static_cast<float>(elapsed));
    return phaseAfterFade(segment, elapsed);
}

void seal(Segment& segment, const anim::ClipLibrary& library, std::uint32_t model) {
    sealSegment(segment.motion, library, model);
}

}  // namespace crowd
