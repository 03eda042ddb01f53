#version 460
#extension GL_GOOGLE_include_directive : require
// The mesh-level cap, per candidate (mesh_cut.glsl.inc): one above the cut's coarse bucket keeps its mesh
// level, one below it is demoted to an impostor, one in it is listed for the resolve pass and counted in
// the fine histogram. With no more candidates than the cap, every one keeps its mesh.
#include "gpu_types.h"
#include "cull_lists.glsl.inc"
#include "mesh_cut.glsl.inc"
#include "mesh_cut_place.glsl.inc"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

void splitCandidate(uint i) {
    uvec2 candidate = candidates[i];
    uint key = candidateKey(candidate);
    uint coarse = coarseBucketOf(key);
    if (meshCut.keepAll != 0u || coarse > meshCut.coarseBucket) {
        keepMesh(candidate);
    } else if (coarse < meshCut.coarseBucket) {
        demote(candidate);
    } else {
        boundary[atomicAdd(meshCut.boundary, 1u)] = i;
        atomicAdd(meshCutWords[FINE_HISTOGRAM + fineBucketOf(key)], 1u);
    }
}

void main() {
    // A grid-stride loop, as culling's: the dispatch is capped at the device's group limit.
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < impostorFrame.meshCount; i += stride) splitCandidate(i);
}
