#version 460
#extension GL_GOOGLE_include_directive : require
// The host's samples in its device buffer (one DeviceSample per slot, written by its own pass this
// frame), made into keys of the characters driven by it: one thread a slot. A sample no later than the
// character's newest key is late (ignored); one with a non-finite time is no sample; one with a
// non-finite position or an infinite heading is refused. Each kind is counted (Renderer::counts).
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

// counts.x: slots, y: threads of the dispatch, z: keys a slot keeps; time.x: the frame's time (s since
// the epoch), w: the epoch's index.
layout(push_constant) uniform Push { MotionPush push; };
layout(std430, set = 0, binding = 0) readonly buffer Motions { MotionRecord motions[]; };
layout(std430, set = 0, binding = 1) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 2) readonly buffer Models { DrivenModel drivenModels[]; };
layout(std430, set = 0, binding = 3) buffer Keys { DrivenKey keys[]; };
layout(std430, set = 0, binding = 4) buffer Heads { uint heads[]; };
layout(std430, set = 0, binding = 5) readonly buffer Samples { DeviceSample samples[]; };
layout(std430, set = 0, binding = 6) buffer Tally { uvec4 tally; };  // x: applied, y: late, z: refused
// Per slot: the generation of the character whose keys the slot's ring holds; another character in the
// slot (a spawn) starts from no key.
layout(std430, set = 0, binding = 7) buffer Owners { uint owners[]; };

// The workgroup's counts, added to the tally once a workgroup (a 10,000,000-slot frame would otherwise
// queue that many atomics on three words).
shared uint applied, late, refused;

#include "driven_keys.h"

void ingest(uint c) {
    if (motions[c].phase.w != MOTION_DRIVEN_DEVICE || !(characters[c].tint.w > 0.0)) return;
    DeviceSample s = samples[c];
    if (isnan(s.time) || isinf(s.time)) return;  // nothing new for it this frame
    if (isnan(s.x) || isinf(s.x) || isnan(s.z) || isinf(s.z) || isinf(s.heading)) {
        atomicAdd(refused, 1u);
        return;
    }
    uint slots = push.counts.x, perSlot = push.counts.z;
    uint generation = floatBitsToUint(characters[c].pose.w);
    uint count = owners[c] == generation ? heads[c] : 0u;
    float epoch = push.time.w, time = push.time.x + s.time;
    DrivenKey previous;
    if (count > 0u) {
        previous = keys[((count - 1u) % perSlot) * slots + c];
        if (!(time > drivenKeyTime(previous, epoch))) {
            atomicAdd(late, 1u);
            return;
        }
    }
    DrivenKey key = drivenKeyAfter(previous, count == 0u, time, epoch, vec2(s.x, s.z), s.heading,
                                   drivenModels[characters[c].ids.x]);
    // A first key with no heading given faces where the character faced.
    if (count == 0u && isnan(s.heading)) key.place.w = characters[c].placement.w;
    keys[(count % perSlot) * slots + c] = key;
    heads[c] = count + 1u;
    owners[c] = generation;
    atomicAdd(applied, 1u);
}

void main() {
    if (gl_LocalInvocationIndex == 0u) applied = late = refused = 0u;
    barrier();
    for (uint c = gl_GlobalInvocationID.x; c < push.counts.x; c += push.counts.y) ingest(c);
    barrier();
    if (gl_LocalInvocationIndex == 0u && applied + late + refused > 0u) {
        atomicAdd(tally.x, applied);
        atomicAdd(tally.y, late);
        atomicAdd(tally.z, refused);
    }
}
