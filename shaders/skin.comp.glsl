#version 460
#extension GL_GOOGLE_include_directive : require
// "compute": skinning in a compute shader, straight into pass 2's vertex buffer.
// A workgroup skins WORKGROUP_SIZE consecutive vertices for CHARACTERS_PER_GROUP characters: the
// characters' bones are staged once in shared memory, and each thread loads its bind-pose vertex
// once and reuses it for every character, so device memory sees little more than the output writes.
#include "gpu_types.h"
#include "skinning.glsl.inc"

// A fixed size (kWorkgroupSize in compute_skinning.cpp): a specialized local size would need maintenance4.
const uint WORKGROUP_SIZE = 64;  // keep equal to local_size_x below
layout(constant_id = 0) const uint CHARACTERS_PER_GROUP = 8;
layout(constant_id = 1) const uint JOINT_COUNT = 32;
layout(local_size_x = 64) in;

layout(push_constant) uniform Push { SkinPassParams params; };  // counts: characters, vertices, -, first character
layout(std430, set = 0, binding = 0) readonly buffer BindPose { SkinVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bones { BoneRows bones[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Normals { vec4 normals[]; };

shared BoneRows groupBones[CHARACTERS_PER_GROUP * JOINT_COUNT];

void main() {
    uint characterCount = params.counts.x;
    uint vertexCount = params.counts.y;
    uint firstCharacter = params.counts.w + gl_WorkGroupID.y * CHARACTERS_PER_GROUP;
    uint boneStride = params.strides.y;

    for (uint i = gl_LocalInvocationIndex; i < CHARACTERS_PER_GROUP * JOINT_COUNT; i += WORKGROUP_SIZE) {
        uint c = firstCharacter + i / JOINT_COUNT;
        if (c < params.counts.w + characterCount) groupBones[i] = bones[c * boneStride + i % JOINT_COUNT];
    }
    barrier();

    uint vertexIndex = gl_GlobalInvocationID.x;
    if (vertexIndex >= vertexCount) return;
    SkinVertex v = vertices[vertexIndex];
    for (uint k = 0; k < CHARACTERS_PER_GROUP; ++k) {
        uint character = firstCharacter + k;
        if (character >= params.counts.w + characterCount) break;
        uint base = k * JOINT_COUNT;
        Skinned s = skinVertex(v, groupBones[base + v.joints.x], groupBones[base + v.joints.y],
                               groupBones[base + v.joints.z], groupBones[base + v.joints.w]);
        uint slot = character * vertexCount + vertexIndex;
        positions[slot] = vec4(s.position, 1.0);
        normals[slot] = vec4(s.normal, v.normal.w);
    }
}
