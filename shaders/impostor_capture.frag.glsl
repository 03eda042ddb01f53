#version 460
#extension GL_GOOGLE_include_directive : require
// The impostor bake's texels: albedo (what the draw pass multiplies by light) and the model-space
// normal, both with coverage in alpha. Empty texels stay (0, 0, 0, 0), so the mip chain holds
// coverage-weighted (premultiplied) values and the impostor divides by alpha.
#include "gpu_types.h"
#include "shading.glsl.inc"
#include "base_color.glsl.inc"

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vAlbedo;
layout(location = 2) in vec2 vUv;
layout(location = 3) flat in uint vTextureSlot;

layout(location = 0) out vec4 outAlbedo;
layout(location = 1) out vec4 outNormal;

void main() {
    outAlbedo = vec4(vAlbedo * sampleBaseColor(vTextureSlot, vUv), 1.0);
    outNormal = vec4(normalize(vNormal) * 0.5 + 0.5, 1.0);
}
