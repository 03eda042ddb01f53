#version 460
#extension GL_GOOGLE_include_directive : require
// The mesh-level cap's last step (mesh_cut.glsl.inc), one workgroup over the members of the cut's coarse
// bucket: the fine histogram gives the exact size of the smallest kept candidate; larger ones keep their
// meshes, smaller ones are demoted. When only some candidates of exactly that size fit, the lower
// character indices keep theirs: their bits in the tie bitset, counted from character 0 up, give the last
// one kept. So exactly the cap's worth keep a mesh level, and none is smaller than one demoted.
#include "gpu_types.h"
#include "cull_lists.glsl.inc"
#include "mesh_cut.glsl.inc"
#include "mesh_cut_place.glsl.inc"
#include "mesh_cut_scan.glsl.inc"

layout(local_size_x = MESH_CUT_WORKGROUP_SIZE) in;

void main() {
    if (meshCut.keepAll != 0u) return;  // the same in every invocation, as are the branches below
    // cut.x: the fine bucket of the smallest kept size; cut.y: how many of exactly that size are kept.
    uvec2 cut = findFromLargest(FINE_HISTOGRAM, MESH_CUT_FINE_BUCKETS, meshCut.keepInCoarse);
    bool tieSplits = cut.y < meshCutWords[FINE_HISTOGRAM + cut.x];
    uint members = meshCut.boundary;
    for (uint k = gl_LocalInvocationIndex; k < members; k += MESH_CUT_WORKGROUP_SIZE) {
        uvec2 candidate = candidates[boundary[k]];
        uint fine = fineBucketOf(candidateKey(candidate));
        if (fine > cut.x || (fine == cut.x && !tieSplits)) keepMesh(candidate);
        else if (fine < cut.x) demote(candidate);
        else atomicOr(meshCutWords[TIE_BITS + candidate.x / 32u], 1u << (candidate.x % 32u));
    }
    if (!tieSplits) return;
    memoryBarrierBuffer();
    barrier();
    uint lastKept = findTiedCharacter((cull.flags.x + 31u) / 32u, cut.y);
    for (uint k = gl_LocalInvocationIndex; k < members; k += MESH_CUT_WORKGROUP_SIZE) {
        uvec2 candidate = candidates[boundary[k]];
        if (fineBucketOf(candidateKey(candidate)) != cut.x) continue;
        if (candidate.x <= lastKept) keepMesh(candidate);
        else demote(candidate);
    }
}
