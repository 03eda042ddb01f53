#version 460
#extension GL_GOOGLE_include_directive : require
// After culling: prefix sums over the buckets (at most MAX_MODELS x LOD_COUNT, so one thread walks
// them) place each bucket's characters in the skinned vertex buffer and the compacted draw list, and
// write the indirect commands whose counts only the GPU knows (the colour pass's and the shadow pass's).
#include "gpu_types.h"

layout(local_size_x = 1) in;

layout(std430, set = 0, binding = 0) readonly buffer Cull { CullUniforms cull; };  // not a uniform buffer (gpu_types.h)
layout(std430, set = 0, binding = 3) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 4) buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 7) writeonly buffer Totals { DrawTotals totals; };
layout(std430, set = 0, binding = 8) writeonly buffer BucketDraws { DrawIndexedCommand bucketDraws[]; };
layout(std430, set = 0, binding = 9) writeonly buffer SkinDispatches { uvec4 skinDispatches[]; };

uint groupsFor(uint items, uint perGroup) { return min((items + perGroup - 1u) / perGroup, cull.limits.x); }

void main() {
    uint vertexBase = 0u;
    uint drawBase = 0u;
    for (uint b = 0u; b < cull.flags.w; ++b) {
        BucketRecord bucket = buckets[b];
        uint count = frames[b].count;
        frames[b].vertexBase = vertexBase;
        frames[b].drawBase = drawBase;
        // vs-instanced: one instanced draw per bucket; instances index the bucket's visible list. Its
        // shadow pass: one per bucket too, after them, over the bucket's list of casters at this level.
        bucketDraws[b] = DrawIndexedCommand(bucket.mesh.y, count, bucket.mesh.x, int(bucket.mesh.w), bucket.list.z);
        bucketDraws[cull.flags.w + b] = DrawIndexedCommand(bucket.mesh.y, frames[b].shadowCount, bucket.mesh.x,
                                                           int(bucket.mesh.w), cull.shadowFlags.y + bucket.list.z);
        // compute skinning: x = groups of characters (a grid-stride loop covers any past the limit),
        // y = groups of CULL_WORKGROUP_SIZE vertices.
        skinDispatches[b] = uvec4(groupsFor(count, bucket.fixedLayout.y), groupsFor(bucket.mesh.z, CULL_WORKGROUP_SIZE), 1u, 0u);
        vertexBase += count * bucket.mesh.z;
        drawBase += count;
    }
    totals.drawCount = drawBase;
    totals.skinnedVertices = vertexBase;
    totals.shadowDrawCount = 0u;  // the emit pass appends the shadow draws
    totals.morphCount = 0u;       // counts the characters morphing between mesh levels
    totals.fading = uvec4(0u);    // and lists those fading into impostors
    totals.emitDispatch = uvec4(groupsFor(drawBase, CULL_WORKGROUP_SIZE), 1u, 1u, 0u);
}
