#include "crowd/motion.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "anim/root_motion.h"

namespace crowd {

float motionPhase(const gpu::MotionRecord& segment, float elapsed) {
    // d(phase)/dt rises linearly from the from-clip's rate to the to-clip's over the crossfade, so the
    // phase is quadratic there and linear after it.
    const float fade = segment.timing.y, from = segment.phase.y, to = segment.phase.z;
    if (fade <= 0.0f) return segment.phase.x + to * elapsed;
    if (elapsed < fade) return segment.phase.x + from * elapsed + (to - from) * elapsed * elapsed / (2.0f * fade);
    return segment.phase.x + 0.5f * (from + to) * fade + to * (elapsed - fade);
}

float motionWeight(const gpu::MotionRecord& segment, float elapsed) {
    const float fade = segment.timing.y;
    return fade > 0.0f ? std::min(elapsed / fade, 1.0f) : 1.0f;
}

float motionHeading(const gpu::MotionRecord& segment, float elapsed) {
    return segment.origin.w + segment.timing.z * std::min(elapsed, segment.timing.w);
}

glm::vec2 turnToWorld(glm::vec2 m, float heading) {
    // As characterTransform turns the model: +z forward turns towards +x for a positive heading.
    const float c = std::cos(heading), s = std::sin(heading);
    return {c * m.x + s * m.y, c * m.y - s * m.x};
}

namespace {

glm::vec2 rootStep(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float a, float b) {
    return library.rootMotion(model, clip, b) - library.rootMotion(model, clip, a);
}

// Displacement along the segment's curved part (turning, crossfading) from its start to `curved`
// seconds: the midpoint rule over MOTION_QUADRATURE_STEPS steps, each step's root motion exact for
// its phases, only its direction and blend weight taken at its middle.
glm::vec2 travelledCurving(const gpu::MotionRecord& segment, float curved, const anim::ClipLibrary& library,
                           std::uint32_t model) {
    // Planning evaluates this inside its solves (thousands of times a frame in a large milling crowd):
    // each step's end is the next step's start, so each clip's root motion is looked up once per step.
    // The arithmetic is the GPU's (shaders/motion.glsl.inc), step for step, and what is skipped here
    // cannot change a bit of it: the from-clip's motion once its weight is 0 (the weight only grows,
    // and 0 times a finite step adds nothing), the to-clip's lookup when it is the same clip, and a
    // heading's sine and cosine when the heading has not changed since the last step.
    const glm::vec2* fromSamples = library.rootMotionSamples(model, segment.clips.x);
    const glm::vec2* toSamples = library.rootMotionSamples(model, segment.clips.y);
    const bool sameClip = fromSamples == toSamples;
    glm::vec2 offset(0.0f);
    if (curved > 0.0f) {
        const float h = curved / static_cast<float>(MOTION_QUADRATURE_STEPS);
        const float phaseStart = motionPhase(segment, 0.0f);
        glm::vec2 toA = anim::rootMotionAt(toSamples, phaseStart);
        glm::vec2 fromA = sameClip ? toA : anim::rootMotionAt(fromSamples, phaseStart);
        float heading = std::numeric_limits<float>::quiet_NaN(), c = 0.0f, s = 0.0f;
        for (int k = 0; k < MOTION_QUADRATURE_STEPS; ++k) {
            const float phaseB = motionPhase(segment, h * static_cast<float>(k + 1));
            const float middle = h * (static_cast<float>(k) + 0.5f);
            const float w = motionWeight(segment, middle);
            const glm::vec2 toB = anim::rootMotionAt(toSamples, phaseB);
            glm::vec2 step = (toB - toA) * w;
            if (w < 1.0f) {
                const glm::vec2 fromB = sameClip ? toB : anim::rootMotionAt(fromSamples, phaseB);
                step = (fromB - fromA) * (1.0f - w) + step;
                fromA = fromB;
            }
            const float stepHeading = motionHeading(segment, middle);
            if (stepHeading != heading) heading = stepHeading, c = std::cos(heading), s = std::sin(heading);
            offset += glm::vec2(c * step.x + s * step.y, c * step.y - s * step.x);  // turnToWorld's
            toA = toB;
        }
    }
    return offset;
}

float windowOf(const gpu::MotionRecord& segment) { return std::max(segment.timing.y, segment.timing.w); }

// Displacement along the segment's path from its start to `elapsed`, in world space (x, z): the curved
// part while in it, then where it ended (sealed) plus a straight line along the to-clip's root
// motion, exact however long the segment.
glm::vec2 travelled(const gpu::MotionRecord& segment, float elapsed, const anim::ClipLibrary& library,
                    std::uint32_t model) {
    const float window = windowOf(segment);
    if (elapsed <= window) return travelledCurving(segment, elapsed, library, model);
    const glm::vec2 curvedEnd(std::bit_cast<float>(segment.clips.z), std::bit_cast<float>(segment.clips.w));
    return curvedEnd + turnToWorld(rootStep(library, model, segment.clips.y, motionPhase(segment, window),
                                            motionPhase(segment, elapsed)),
                                   motionHeading(segment, window));
}

}  // namespace

void sealSegment(gpu::MotionRecord& segment, const anim::ClipLibrary& library, std::uint32_t model) {
    const glm::vec2 end = segment.phase.w == MOTION_ROOT ? travelledCurving(segment, windowOf(segment), library, model)
                                                  : glm::vec2(0.0f);
    segment.clips.z = std::bit_cast<std::uint32_t>(end.x);
    segment.clips.w = std::bit_cast<std::uint32_t>(end.y);
}

MotionState evaluateMotion(const gpu::MotionRecord& segment, float time, const anim::ClipLibrary& library,
                           std::uint32_t model) {
    const float elapsed = std::max(time - segment.timing.x, 0.0f);
    MotionState state;
    state.position = glm::vec3(segment.origin);
    if (segment.phase.w == MOTION_ROOT) {
        const glm::vec2 offset = travelled(segment, elapsed, library, model);
        state.position.x += offset.x;
        state.position.z += offset.y;
    }
    state.heading = motionHeading(segment, elapsed);
    state.clipFrom = segment.clips.x;
    state.clipTo = segment.clips.y;
    state.phase = motionPhase(segment, elapsed);
    state.weight = motionWeight(segment, elapsed);
    return state;
}

float cyclesPerSecond(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float rate) {
    if (clip >= library.clipCount(model)) return 0.0f;
    const float duration = library.duration(model, clip);
    return duration > 0.0f ? rate / duration : 0.0f;
}

double exactCyclesPerSecond(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float rate) {
    if (clip >= library.clipCount(model)) return 0.0;
    const double duration = library.duration(model, clip);
    return duration > 0.0 ? rate / duration : 0.0;
}

gpu::MotionRecord inPlaceSegment(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip,
                                 const glm::vec3& position, float heading, float start, float phase, float rate) {
    gpu::MotionRecord segment{};
    const float cycles = cyclesPerSecond(library, model, clip, rate);
    segment.origin = glm::vec4(position, heading);
    segment.timing = glm::vec4(start, 0.0f, 0.0f, 0.0f);
    segment.phase = glm::vec4(phase, cycles, cycles, 0.0f);
    segment.clips = glm::uvec4(clip, clip, 0u, 0u);
    return segment;
}

}  // namespace crowd
