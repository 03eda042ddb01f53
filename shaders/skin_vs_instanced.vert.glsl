#version 460
#extension GL_GOOGLE_include_directive : require
// "vs-instanced", the modern baseline: vertex-shader skinning with every character in one instanced
// draw; the instance index selects the character's bones in a storage buffer.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"

layout(constant_id = 0) const uint BONE_STRIDE = 64;

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(std430, set = 1, binding = 0) readonly buffer Bones { BoneRows bones[]; };

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
    uint base = uint(gl_InstanceIndex) * BONE_STRIDE;
    Skinned s = skinVertex(v, bones[base + inJoints.x], bones[base + inJoints.y], bones[base + inJoints.z],
                           bones[base + inJoints.w]);
    gl_Position = scene.viewProjection * vec4(s.position, 1.0);
    outNormal = s.normal;
    outAlbedo = characterColor(scene, uint(inNormal.w), uint(gl_InstanceIndex));
    outUv = textureCoordinates[uint(gl_VertexIndex)];
    outTextured = isTextured(scene, uint(inNormal.w));
    outWorld = s.position;
}
