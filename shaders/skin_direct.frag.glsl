#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1 of "two-pass-direct": the paper's fragment-shader skinning, but each fragment stores its
// skinned vertex straight into pass 2's vertex buffer (bound as a storage buffer). No RGBA32F image
// and no image-to-buffer copy: the difference to "two-pass" is what that copy costs.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "skin_texel.glsl.inc"

layout(push_constant) uniform Push { SkinPassParams params; };
layout(std430, set = 0, binding = 0) readonly buffer BindPose { SkinVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bones { BoneRows bones[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Normals { vec4 normals[]; };

void main() {
    uint character, vertexIndex;
    if (!texelToCharacterVertex(params, uvec2(gl_FragCoord.xy), character, vertexIndex)) return;
    SkinVertex v = vertices[vertexIndex];
    uint base = character * params.strides.y;
    Skinned s = skinVertex(v, bones[base + v.joints.x], bones[base + v.joints.y],
                           bones[base + v.joints.z], bones[base + v.joints.w]);
    // Same place the image copy would put it: character-major, characterStride = width * rows.
    uint slot = character * params.strides.x * params.counts.z + vertexIndex;
    positions[slot] = vec4(s.position, 1.0);
    normals[slot] = vec4(s.normal, v.normal.w);
}
