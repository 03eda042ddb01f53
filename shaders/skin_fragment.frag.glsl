#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1, the paper's idea: skinning in a fragment shader. Each texel of the RGBA32F targets is one
// (character, vertex); the fragment skins that vertex with that character's bones and writes the
// world-space position and normal, which a copy then turns into pass 2's vertex buffer.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "skin_texel.glsl.inc"

layout(push_constant) uniform Push { SkinPassParams params; };
layout(std430, set = 0, binding = 0) readonly buffer BindPose { SkinVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bones { BoneRows bones[]; };

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

void main() {
    // Texel layout: each character owns `rowsPerCharacter` consecutive rows; its vertices run
    // along them left to right. Copied row by row, the image becomes a character-major vertex
    // buffer that the unmodified index buffer draws with vertexOffset = character * rowStride.
    uint character, vertexIndex;
    if (!texelToCharacterVertex(params, uvec2(gl_FragCoord.xy), character, vertexIndex)) {
        outPosition = vec4(0.0);  // padding texels past the last vertex: never drawn
        outNormal = vec4(0.0);
        return;
    }
    SkinVertex v = vertices[vertexIndex];
    uint base = character * params.strides.y;
    Skinned s = skinVertex(v, bones[base + v.joints.x], bones[base + v.joints.y],
                           bones[base + v.joints.z], bones[base + v.joints.w]);
    outPosition = vec4(s.position, 1.0);
    outNormal = vec4(s.normal, v.normal.w);
}
