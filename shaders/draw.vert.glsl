#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_draw_parameters : require
// Pass 2: draws characters from already-skinned world-space vertices (position, normal + material).
#include "gpu_types.h"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outAlbedo;
layout(location = 2) out vec3 outWorld;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out uint outTextured;

void main() {
    gl_Position = scene.viewProjection * vec4(inPosition.xyz, 1.0);
    outNormal = inNormal.xyz;
    // The skinned buffer holds every character; minus the draw's vertexOffset, the index is the model's.
    // firstInstance carries the character index, for its colour variation.
    outAlbedo = characterColor(scene, uint(inNormal.w), uint(gl_InstanceIndex));
    outUv = textureCoordinates[uint(gl_VertexIndex - gl_BaseVertexARB)];
    outTextured = isTextured(scene, uint(inNormal.w));
    outWorld = inPosition.xyz;
}
