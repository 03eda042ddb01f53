#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting of characters, shared by every skinning method.
#include "gpu_types.h"
#include "shading.glsl.inc"
#define VARYING in
#include "draw_varyings.glsl.inc"
#include "base_color.glsl.inc"
#include "fade_dither.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; };
layout(location = 0) out vec4 outColor;
// 1: this pipeline draws characters fading into their impostors, on the pixels the impostor's share of
// the dither leaves them (fade_dither.glsl.inc); 0: every pixel, with no discard, so the depth test
// may stay early (fades between mesh levels are morphs made while skinning, drawn whole).
layout(constant_id = 0) const uint kDithered = 0u;
// 0: no model of the pool has a textured material (GeometryPool::texturedMaterials), so every albedo is
// its colour alone and the texture coordinates go unread: the pipeline then passes them to no fragment.
// Measured on the H200: 0.11 ms of paper-fig4's colour pass, whose soldiers have no texture.
layout(constant_id = 1) const bool kTextured = true;

void main() {
    vec3 albedo = drawAlbedo(vMaterial);
    if (kTextured) albedo *= sampleBaseColor(drawTextureSlot(vMaterial), vUv);
    // After the texture read, which needs its neighbours' coordinates for derivatives.
    if (kDithered != 0u && !fadeDraws(gl_FragCoord.xy, drawFadeShare(vMaterial), false)) discard;
    outColor = vec4(shade(scene, vNormal, albedo, vWorld, cameraPosition.xyz), 1.0);
}
