#version 460
#extension GL_GOOGLE_include_directive : require
// The keys the CPU made of the host's samples since the last frame (crowd::Crowd::drive), packed with
// their slots and indices, scattered into the slots' rings: one thread each; an entry whose slot is past
// the crowd is none. A slot's key count rises
// to the newest key's (atomicMax: several keys of a slot may come in one upload, in any order).
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { MotionPush push; };  // counts.x: keys, y: slots, z: keys a slot keeps
layout(std430, set = 0, binding = 0) readonly buffer Uploaded { DrivenKeyUpload uploaded[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Keys { DrivenKey keys[]; };
layout(std430, set = 0, binding = 2) buffer Heads { uint heads[]; };

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < push.counts.x; i += stride) {
        DrivenKeyUpload u = uploaded[i];
        if (u.target.x >= push.counts.y) continue;  // no key (a late sample's entry, or one its ring dropped)
        keys[(u.target.y % push.counts.z) * push.counts.y + u.target.x] = u.key;
        atomicMax(heads[u.target.x], u.target.y + 1u);
    }
}
