#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting of characters, shared by every skinning method.
#include "gpu_types.h"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; };

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inAlbedo;
layout(location = 2) in vec3 inWorld;
layout(location = 3) in vec2 inUv;
layout(location = 4) flat in uint inTextured;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 albedo = inAlbedo;
    if (inTextured != 0u) albedo *= texture(baseColorTexture, inUv).rgb;
    outColor = vec4(shade(scene, inNormal, albedo, distance(inWorld, cameraPosition.xyz)), 1.0);
}
