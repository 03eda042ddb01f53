#version 460
#extension GL_GOOGLE_include_directive : require
// The paper's baseline: skinning in the vertex shader, each character's bones bound per draw
// (a dynamic uniform-buffer offset plays the part of the paper's constant registers).
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"

layout(constant_id = 0) const uint BONE_COUNT = 64;

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(std140, set = 1, binding = 0) uniform CharacterBones { BoneRows bones[BONE_COUNT]; };

layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;
layout(location = 2) in uvec4 inJoints;
layout(location = 3) in vec4 inWeights;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outAlbedo;
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out uint outTextured;

void main() {
    SkinVertex v = SkinVertex(inPosition, inNormal, inJoints, inWeights);
    Skinned s = skinVertex(v, bones[inJoints.x], bones[inJoints.y], bones[inJoints.z], bones[inJoints.w]);
    gl_Position = scene.viewProjection * vec4(s.position, 1.0);
    outNormal = s.normal;
    outAlbedo = characterColor(scene, uint(inNormal.w), uint(gl_InstanceIndex));
    outUv = textureCoordinates[uint(gl_VertexIndex)];
    outTextured = isTextured(scene, uint(inNormal.w));
    outWorld = s.position;
}
