#version 460
#extension GL_GOOGLE_include_directive : require
// An impostor's pixel: the atlas's albedo and model-space normal blended over eight cells (four where
// the elevation band's share is 0)
// (impostor_sample.glsl.inc; coverage-weighted, so divided by the blended coverage), the normal turned by the heading, and the same lighting as the mesh (shade()), so the
// switch from mesh to impostor keeps the character's brightness. Single-sampled, texels under half
// coverage are cut; multisampled, the coverage goes out as alpha and the pipeline's alpha to coverage
// turns it into the share of the pixel's samples the impostor covers. Either way the coverage is the
// blended one, the same the shadow pass cuts at half.
// The lighting is impostor_shade.glsl.inc's, shared with the compute rasterizer's resolve.
#include "gpu_types.h"
#include "shading.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_sample.glsl.inc"
#include "fade_dither.glsl.inc"
#include "impostor_normal.glsl.inc"
#include "impostor_shade.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(set = 2, binding = 0) uniform sampler2DArray atlasAlbedo;
layout(set = 2, binding = 1) uniform sampler2DArray atlasNormal;
layout(push_constant) uniform Push { vec4 cameraPosition; };
layout(constant_id = 0) const bool kAlphaToCoverage = false;
layout(constant_id = 1) const bool kBlend = true;  // impostor-blend: the cells' blend, or the nearest one's texel

layout(location = 0) in vec2 vLocal;
layout(location = 1) flat in uvec4 vCells;
layout(location = 2) flat in vec3 vTint;
layout(location = 3) flat in vec2 vHeading;
layout(location = 4) in vec3 vWorld;
layout(location = 5) flat in float vRadius;
layout(location = 6) flat in vec3 vWeights;
layout(location = 7) flat in uvec2 vGrid;
layout(location = 8) flat in float vFadeShare;
layout(location = 9) flat in uint vBandStep;
layout(location = 0) out vec4 outColor;

void main() {
    const ImpostorBlend cells = ImpostorBlend(vCells, vBandStep, vWeights);
    vec4 albedo = impostorTexel(atlasAlbedo, kBlend, cells, vGrid, vLocal);
    if (albedo.a < (kAlphaToCoverage ? 1.0 / 255.0 : 0.5)) discard;  // (nothing covered: no depth either)
    vec3 lit = impostorShade(scene, atlasNormal, kBlend, cells, vGrid, vLocal, albedo, vTint, vHeading, vWorld,
                             vRadius, cameraPosition.xyz);
    // Fading from its last mesh level (which draws the other pixels): the coarser level's share. After
    // the texture reads, which need their neighbours' places for derivatives.
    if (vFadeShare > 0.0 && !fadeDraws(gl_FragCoord.xy, vFadeShare, true)) discard;
    // Alpha to coverage reads the coverage from alpha (and the pipeline does not write it); single-sampled
    // the pixel is opaque.
    outColor = vec4(lit, kAlphaToCoverage ? albedo.a : 1.0);
}
