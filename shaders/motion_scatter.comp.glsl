#version 460
#extension GL_GOOGLE_include_directive : require
// The segments the CPU replanned this frame, packed in an upload buffer with their characters'
// indices, scattered to their characters' places: one thread each. (A copy region per segment costs
// the copy engine microseconds apiece; thousands of replans a frame would take milliseconds.)
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };  // counts.x: segments in the upload
layout(std430, set = 0, binding = 0) readonly buffer Uploaded { MotionRecord uploaded[]; };
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Motions { MotionRecord motions[]; };

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < push.counts.x; i += stride) motions[indices[i]] = uploaded[i];
}
