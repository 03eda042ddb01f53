#version 460
#extension GL_GOOGLE_include_directive : require
// The start times of the segments the CPU replanned this frame (for the event pass, render/event_pass.h),
// packed in an upload buffer with their characters' indices, scattered to their characters' places: one
// thread each. As motion_scatter.comp.glsl does for the segments: a copy region per character costs the
// driver and the copy engine far more, and thousands replan a frame.
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };  // counts.x: starts in the upload
layout(std430, set = 0, binding = 0) readonly buffer Uploaded { float uploaded[]; };
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Starts { float starts[]; };

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < push.counts.x; i += stride) starts[indices[i]] = uploaded[i];
}
