#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 2: draws characters from already-skinned world-space vertices (position, normal + material).
#include "gpu_types.h"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outAlbedo;
layout(location = 2) out vec3 outWorld;

void main() {
    gl_Position = scene.viewProjection * vec4(inPosition.xyz, 1.0);
    outNormal = inNormal.xyz;
    // firstInstance carries the character index, for its colour variation.
    outAlbedo = characterColor(scene, uint(inNormal.w), uint(gl_InstanceIndex));
    outWorld = inPosition.xyz;
}
