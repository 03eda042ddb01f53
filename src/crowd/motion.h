#pragma once
// A character's motion as closed-form segments. The CPU plans a segment when the previous one ends
// (crowd/behaviours.h) or when a program commands it (crowd/crowd.h); CPU and GPU then evaluate it at
// any later time without stepping through the frames between (shaders/motion.glsl.inc repeats these
// operations). So off-screen characters keep exact time and position for free, frame rate never
// changes where anyone is, and the GPU needs no upload except the segments the CPU replans.
//
// Within a segment the character crossfades from one clip to another (weight rising linearly over
// the crossfade) with their phases synchronized: both clips sit at the same point of their cycles,
// which advances at the blend of the clips' rates, so a walk->run keeps the feet in step. It turns
// at a constant rate for a while, and moves along its clips' root motion (model/measure_root_motion.h)
// so planted feet stay planted.
#include <cstdint>

#include <glm/glm.hpp>

#include "anim/clip_library.h"
#include "gpu_types.h"

namespace crowd {

// Where a character is and what it plays at one moment.
struct MotionState {
    glm::vec3 position{0.0f};
    float heading = 0.0f;
    std::uint32_t clipFrom = 0, clipTo = 0;  // the model's clip indices
    float phase = 0.0f;                      // normalized phase, in cycles
    float weight = 1.0f;                     // of clipTo
};

// The state of a character of `model` following `segment` at `time` (times before the segment's
// start give its start).
MotionState evaluateMotion(const gpu::MotionRecord& segment, float time, const anim::ClipLibrary& library,
                           std::uint32_t model);

// Integrates the segment's curved part (its turn and crossfade, by quadrature) once and stores where it
// ends in the segment, so evaluating it later costs a few operations instead of the quadrature. Every
// planned segment is sealed before anyone evaluates it.
void sealSegment(gpu::MotionRecord& segment, const anim::ClipLibrary& library, std::uint32_t model);

// The normalized phase `elapsed` seconds into a segment, and the crossfade weight then.
float motionPhase(const gpu::MotionRecord& segment, float elapsed);
float motionWeight(const gpu::MotionRecord& segment, float elapsed);
float motionHeading(const gpu::MotionRecord& segment, float elapsed);

// A segment playing `clip` of `model` in place from `start`, at `phase` cycles then, `rate` times its
// natural speed: what a character of the paper's crowd does forever.
gpu::MotionRecord inPlaceSegment(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip,
                                 const glm::vec3& position, float heading, float start, float phase, float rate);

// Cycles per second of a model's clip played `rate` times its natural speed (0 for a clip of no length).
float cyclesPerSecond(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float rate);
// The same in double, for what must stay exact over hours (crowd::Segment::rate).
double exactCyclesPerSecond(const anim::ClipLibrary& library, std::uint32_t model, std::uint32_t clip, float rate);

// The world-space direction of a model-space (x, z) displacement for a character facing `heading`.
glm::vec2 turnToWorld(glm::vec2 modelSpace, float heading);

}  // namespace crowd
