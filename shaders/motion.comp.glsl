#version 460
#extension GL_GOOGLE_include_directive : require
// The motion pass: one thread per character evaluates its motion segment at this frame's time and
// writes where it is, which way it faces and what it plays into its CharacterRecord, which culling,
// the palette pass, skinning and drawing then read. Every character, seen or not: the closed form
// costs a few dozen operations, and off-screen characters must be where culling can find them.
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };
layout(std430, set = 0, binding = 0) readonly buffer Models { AnimationModel animModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Clips { AnimationClip animClips[]; };
layout(std430, set = 0, binding = 2) readonly buffer RootSamples { vec2 rootSamples[]; };
layout(std430, set = 0, binding = 3) readonly buffer Motions { MotionRecord motions[]; };
layout(std430, set = 0, binding = 4) buffer Characters { CharacterRecord characters[]; };

#include "motion.glsl.inc"

void moveCharacter(uint c) {
    MotionRecord m = motions[c];
    uint model = characters[c].ids.x;
    uint firstClip = animModels[model].info.z;
    float elapsed = max(push.time.x - m.timing.x, 0.0);
    vec3 position = m.origin.xyz;
    if (m.phase.w != 0.0) {
        vec2 offset = travelled(m, elapsed, firstClip + m.clips.x, firstClip + m.clips.y);
        position.xz += offset;
    }
    characters[c].placement = vec4(position, motionHeading(m, elapsed));
    characters[c].ids.w = m.clips.x | (m.clips.y << 16u);
    characters[c].pose.xy = vec2(motionPhase(m, elapsed), motionWeight(m, elapsed));  // z: its props, fixed
}

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint c = gl_GlobalInvocationID.x; c < push.counts.x; c += stride) moveCharacter(c);
}
