#version 460
#extension GL_GOOGLE_include_directive : require
// An impostor's pixel: the atlas's albedo and model-space normal blended over eight cells (four where
// the elevation band's share is 0)
// (impostor_sample.glsl.inc; coverage-weighted, so divided by the blended coverage), the normal turned by the heading, and the same lighting as the mesh (shade()), so the
// switch from mesh to impostor keeps the character's brightness. Single-sampled, texels under half
// coverage are cut; multisampled, the coverage becomes the share of the pixel's samples the impostor
// covers (coveredSamples). Either way the coverage is the blended one, the same the shadow pass cuts at
// half.
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
layout(constant_id = 0) const uint kSamples = 1u;  // of the target: 1 cuts at half coverage
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

// The sample mask of a texel's coverage: that share of the pixel's samples, rounded, as the pipeline's
// alpha to coverage would make it, but with the alpha written left at 1. (Alpha to coverage would
// leave the covered samples' alpha unwritten, and with the sky in place of a clear nothing else writes
// it.) The samples taken turn with the pixel, so overlapping impostors do not all take the same ones.
// Single-sampled: the one sample, the texel being at least half covered.
int coveredSamples(float coverage) {
    uint taken = min(uint(coverage * float(kSamples) + 0.5), kSamples);
    uint all = (1u << kSamples) - 1u;
    uint mask = (1u << taken) - 1u;
    uint turn = (uint(gl_FragCoord.x) + 2u * uint(gl_FragCoord.y)) % kSamples;
    return int(((mask << turn) | (mask >> (kSamples - turn))) & all);
}

void main() {
    const ImpostorBlend cells = ImpostorBlend(vCells, vBandStep, vWeights);
    vec4 albedo = impostorTexel(atlasAlbedo, kBlend, cells, vGrid, vLocal);
    // Nothing covered (under half a sample), no depth either.
    if (albedo.a < 0.5 / float(kSamples)) discard;
    vec3 lit = impostorShade(scene, atlasNormal, kBlend, cells, vGrid, vLocal, albedo, vTint, vHeading, vWorld,
                             vRadius, cameraPosition.xyz);
    // Fading from its last mesh level (which draws the other pixels): the coarser level's share. After
    // the texture reads, which need their neighbours' places for derivatives.
    if (vFadeShare > 0.0 && !fadeDraws(gl_FragCoord.xy, vFadeShare, true)) discard;
    // On every path: a shader that writes the mask somewhere leaves it undefined where it does not.
    gl_SampleMask[0] = coveredSamples(albedo.a);
    outColor = vec4(lit, 1.0);
}
