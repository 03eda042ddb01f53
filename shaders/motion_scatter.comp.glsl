#version 460
#extension GL_GOOGLE_include_directive : require
// The slots the crowd changed since the last frame (replans, spawns, removals), packed in an upload buffer
// with their indices: each one's segment, and its identity (tint and scale, 0 for a free slot; the props
// it carries) into its character record, scattered to their places: one thread each. (A copy region per
// slot costs the copy engine microseconds apiece; thousands of replans a frame would take milliseconds.)
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };  // counts.x: segments in the upload
layout(std430, set = 0, binding = 0) readonly buffer Uploaded { MotionRecord uploaded[]; };
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Motions { MotionRecord motions[]; };
layout(std430, set = 0, binding = 3) readonly buffer Tints { vec4 tints[]; };
layout(std430, set = 0, binding = 4) readonly buffer Words { uvec2 words[]; };  // x: props, y: the slot's generation
layout(std430, set = 0, binding = 5) buffer Characters { CharacterRecord characters[]; };
// A character driven from the host's memory: its key count (its keys follow, render/driven_pass.h);
// 0xFFFFFFFF leaves a device-driven slot's count to the GPU's ingest.
layout(std430, set = 0, binding = 6) readonly buffer KeyCounts { uint keyCounts[]; };
layout(std430, set = 0, binding = 7) buffer Heads { uint heads[]; };

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < push.counts.x; i += stride) {
        uint c = indices[i];
        motions[c] = uploaded[i];
        characters[c].tint = tints[i];
        characters[c].pose.zw = vec2(float(words[i].x), uintBitsToFloat(words[i].y));
        if (keyCounts[i] != 0xFFFFFFFFu) heads[c] = keyCounts[i];
    }
}
