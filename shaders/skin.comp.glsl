#version 460
#extension GL_GOOGLE_include_directive : require
// "compute": skinning in a compute shader, straight into the draw pass's vertex buffer; one dispatch
// per (model, LOD) bucket, sized by culling (an indirect dispatch). A workgroup skins
// CULL_WORKGROUP_SIZE consecutive vertices of the LOD for CHARACTERS_PER_GROUP visible characters: their
// bones are staged once in shared memory, and each thread loads its bind-pose vertex once and reuses
// it for every character, so device memory sees little more than the output writes. A character
// fading into its coarser mesh level has the vertices that level drops morphed toward it
// (lod_morph.glsl.inc): the group's shares are staged with its bones.
#include "gpu_types.h"
#include "skinning.glsl.inc"

layout(constant_id = 0) const uint CHARACTERS_PER_GROUP = 8;
layout(constant_id = 1) const uint JOINT_COUNT = 32;  // of this pipeline's model
// 1: this pipeline skins buckets of a level with a coarser mesh level, whose characters may morph
// into it; 0 (the last level, the static ceiling): none does, and the morph's code is left out.
layout(constant_id = 2) const uint MORPHS = 1;
layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { SkinPassParams params; };
layout(std430, set = 0, binding = 0) readonly buffer BindPose { SkinVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bones { BoneRows bones[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Normals { vec4 normals[]; };
layout(std430, set = 0, binding = 4) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 5) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 6) readonly buffer Frames { BucketFrame frames[]; };
// This frame's visible characters, or (fixed layout) every character of the model in rank order.
layout(std430, set = 0, binding = 7) readonly buffer List { uint list[]; };
layout(std430, set = 0, binding = 8) readonly buffer States { uint states[]; };  // gpu_types.h, FADE_SHIFT
layout(std430, set = 0, binding = 9) readonly buffer MorphTargets { LodMorphTarget morphTargets[]; };

shared BoneRows groupBones[CHARACTERS_PER_GROUP * JOINT_COUNT];
shared float groupShares[CHARACTERS_PER_GROUP];  // each character's share of its coarser level

#define LOD_MORPH_BONE(i) groupBones[i]
#include "lod_morph.glsl.inc"

void main() {
    BucketRecord bucket = buckets[params.bucket.x];
    bool fixedLayout = params.bucket.y != 0u;
    uint count = fixedLayout ? bucket.list.w : frames[params.bucket.x].count;
    uint vertexBase = fixedLayout ? bucket.fixedLayout.x : frames[params.bucket.x].vertexBase;
    uint vertexCount = bucket.mesh.z;
    uint vertexIndex = gl_WorkGroupID.y * CULL_WORKGROUP_SIZE + gl_LocalInvocationIndex;
    SkinVertex v;
    if (vertexIndex < vertexCount) v = vertices[bucket.mesh.w + vertexIndex];
    bool moves = MORPHS != 0u && vertexIndex < vertexCount && lodMorphMoves(params.bucket.x, vertexIndex);

    // A grid-stride loop over groups of characters: a bucket larger than one dispatch's x limit
    // takes several turns. The loop bound is the same for the whole workgroup, as barrier() needs.
    for (uint group = gl_WorkGroupID.x; group * CHARACTERS_PER_GROUP < count; group += gl_NumWorkGroups.x) {
        uint first = group * CHARACTERS_PER_GROUP;
        barrier();  // the previous turn's threads are done reading the shared bones
        for (uint i = gl_LocalInvocationIndex; i < CHARACTERS_PER_GROUP * JOINT_COUNT; i += CULL_WORKGROUP_SIZE) {
            uint k = first + i / JOINT_COUNT;
            if (k < count) groupBones[i] = bones[characters[list[bucket.list.z + k]].ids.y + i % JOINT_COUNT];
        }
        if (MORPHS != 0u && gl_LocalInvocationIndex < CHARACTERS_PER_GROUP) {
            uint k = first + gl_LocalInvocationIndex;
            groupShares[gl_LocalInvocationIndex] = k < count ? lodMorphShare(states[list[bucket.list.z + k]]) : 0.0;
        }
        barrier();
        if (vertexIndex >= vertexCount) continue;
        for (uint j = 0u; j < CHARACTERS_PER_GROUP && first + j < count; ++j) {
            uint base = j * JOINT_COUNT;
            Skinned s = skinVertex(v, groupBones[base + v.joints.x], groupBones[base + v.joints.y],
                                   groupBones[base + v.joints.z], groupBones[base + v.joints.w]);
            // Few characters fade: their targets are read when needed, not held by every thread.
            if (moves && groupShares[j] > 0.0) s = lodMorphed(s, lodMorphOf(bucket.mesh.w, vertexIndex), base, groupShares[j]);
            uint slot = vertexBase + (first + j) * vertexCount + vertexIndex;
            positions[slot] = vec4(s.position, 1.0);
            normals[slot] = vec4(s.normal, v.normal.w);
        }
    }
}
