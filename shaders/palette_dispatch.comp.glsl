#version 460
#extension GL_GOOGLE_include_directive : require
// After culling: one indirect dispatch per bucket for the palette pass, sized by the bucket's
// visible count (only the GPU knows it) and its model's characters per workgroup.
#include "gpu_types.h"

layout(local_size_x = 1) in;

layout(push_constant) uniform Push { PalettePush push; };
layout(std430, set = 0, binding = 0) readonly buffer Models { AnimationModel animModels[]; };
layout(std430, set = 0, binding = 7) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 8) readonly buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 11) writeonly buffer Dispatches { uvec4 dispatches[]; };

void main() {
    for (uint b = 0u; b < push.bucket.x; ++b) {
        uint joints = animModels[buckets[b].list.x].info.y;
        uint perGroup = max(1u, 64u / joints);
        uint groups = (frames[b].count + perGroup - 1u) / perGroup;
        dispatches[b] = uvec4(min(groups, push.bucket.y), 1u, 1u, 0u);
    }
}
