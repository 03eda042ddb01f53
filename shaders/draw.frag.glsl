#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting of characters, shared by every skinning method.
#include "gpu_types.h"
#include "shading.glsl.inc"
#define VARYING in
#include "draw_varyings.glsl.inc"
#include "base_color.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; };
layout(location = 0) out vec4 outColor;

void main() {
    vec3 albedo = vAlbedo * sampleBaseColor(vTextureSlot, vUv);
    outColor = vec4(shade(scene, vNormal, albedo, vWorld, cameraPosition.xyz), 1.0);
}
