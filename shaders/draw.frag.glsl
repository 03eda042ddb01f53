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
// Which level of a fading character this pipeline draws (fade_dither.glsl.inc): 0 no fades (every
// pixel; no discard, so the depth test may stay early), 1 the finer level (the colour draws: a
// character not fading has a share of 0 and keeps every pixel), 2 the coarser (the fade partners' draws).
layout(constant_id = 0) const uint kFadeSide = 0u;

void main() {
    vec3 albedo = drawAlbedo(vMaterial) * sampleBaseColor(drawTextureSlot(vMaterial), vUv);
    // After the texture read, which needs its neighbours' coordinates for derivatives.
    if (kFadeSide != 0u && !fadeDraws(gl_FragCoord.xy, drawFadeShare(vMaterial), kFadeSide == 2u)) discard;
    outColor = vec4(shade(scene, vNormal, albedo, vWorld, cameraPosition.xyz), 1.0);
}
