#version 460
#extension GL_GOOGLE_include_directive : require
// The mesh-level cap, after culling (mesh_cut.glsl.inc): when more characters qualified for a mesh level
// than the cap, the coarse size bucket that the cut falls in, found by one workgroup walking the coarse
// histogram from the largest sizes down; and the split pass's dispatch over the candidates.
#include "gpu_types.h"
#include "mesh_cut.glsl.inc"
#include "mesh_cut_scan.glsl.inc"

layout(local_size_x = MESH_CUT_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = 0) readonly buffer Cull { CullUniforms cull; };  // not a uniform buffer (gpu_types.h)
layout(std430, set = 0, binding = 12) buffer Impostors { ImpostorFrame impostorFrame; };

void main() {
    uint candidates = impostorFrame.meshCount;
    uint capacity = cull.limits.z;
    bool keepAll = candidates <= capacity;  // the same in every invocation: the search below is reached by all or none
    uvec2 cut = keepAll ? uvec2(0u) : findFromLargest(COARSE_HISTOGRAM, MESH_CUT_COARSE_BUCKETS, capacity);
    if (gl_LocalInvocationIndex != 0u) return;
    meshCut.keepAll = keepAll ? 1u : 0u;
    meshCut.coarseBucket = cut.x;
    meshCut.keepInCoarse = cut.y;
    impostorFrame.demoted = keepAll ? 0u : candidates - capacity;
    uint groups = min((candidates + CULL_WORKGROUP_SIZE - 1u) / CULL_WORKGROUP_SIZE, cull.limits.x);
    meshCut.splitDispatch = uvec4(groups, 1u, 1u, 0u);
}
