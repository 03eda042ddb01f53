#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting of characters, shared by every skinning method.
#include "gpu_types.h"
#include "shading.glsl.inc"
#define VARYING in
#include "draw_varyings.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; };
layout(location = 0) out vec4 outColor;

// Sampler arrays indexed by a variable need shaderSampledImageArrayDynamicIndexing, which lavapipe
// lacks; constant indices need nothing. The slot is one model's for a whole draw, so the branch is
// uniform and costs little.
vec3 sampleBaseColor(uint slot, vec2 uv) {
    switch (slot) {
        case 1u: return texture(baseColorTextures[1], uv).rgb;
        case 2u: return texture(baseColorTextures[2], uv).rgb;
        case 3u: return texture(baseColorTextures[3], uv).rgb;
        case 4u: return texture(baseColorTextures[4], uv).rgb;
        case 5u: return texture(baseColorTextures[5], uv).rgb;
        case 6u: return texture(baseColorTextures[6], uv).rgb;
        case 7u: return texture(baseColorTextures[7], uv).rgb;
        default: return texture(baseColorTextures[0], uv).rgb;
    }
}

void main() {
    vec3 albedo = vAlbedo * sampleBaseColor(vTextureSlot, vUv);
    outColor = vec4(shade(scene, vNormal, albedo, vWorld, cameraPosition.xyz), 1.0);
}
