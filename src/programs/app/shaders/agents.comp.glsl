#version 460
#extension GL_GOOGLE_include_directive : require
// The benchmarks' GPU simulation (app/agent_drivers.h): one thread an agent writes where it is now as the
// crowd's device sample of its slot, as a host's own simulation pass would, with no CPU copy.
#include "gpu_types.h"
#include "agent_path.h"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
    uint agents;   // slots
    uint stride;   // threads of the dispatch
    float time;    // seconds since the agents' clock began (they are sampled at the frame's time: sample time 0)
    float unused;
} push;
layout(std430, set = 0, binding = 0) readonly buffer Homes { vec2 homes[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Samples { DeviceSample samples[]; };

void main() {
    for (uint i = gl_GlobalInvocationID.x; i < push.agents; i += push.stride) {
        vec2 p = agentPosition(i, homes[i], push.time);
        samples[i] = DeviceSample(0.0, p.x, p.y, uintBitsToFloat(0x7FC00000u));  // now; heading: the motion's
    }
}
