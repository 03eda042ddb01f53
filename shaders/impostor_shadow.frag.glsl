#version 460
#extension GL_GOOGLE_include_directive : require
// An impostor's quad in the shadow map (depth only): the atlas texels the colour pass keeps (at least
// half coverage) cast, the rest do not. The coverage is blended between the two nearest frames at the
// nearer azimuth (impostorShadowCoverage, impostor_sample.glsl.inc), so a walking character's shadow
// morphs with it rather than jumping a frame on the ground; in the nearest elevation band only, the one
// the vertex shader left (the light is fixed, so the band it sees a still character from never changes).
#include "gpu_types.h"
#include "impostor_cell.glsl.inc"
#include "impostor_sample.glsl.inc"

layout(set = 2, binding = 0) uniform sampler2DArray atlasAlbedo;

layout(location = 0) in vec2 vLocal;
layout(location = 1) flat in uvec4 vCells;
// The colour pass's inputs, unused here: declared so the vertex shader's outputs all have a consumer.
layout(location = 2) flat in vec3 vTint;
layout(location = 3) flat in vec2 vHeading;
layout(location = 4) in vec3 vWorld;
layout(location = 5) flat in float vRadius;
layout(location = 6) flat in vec3 vWeights;
layout(location = 7) flat in uvec2 vGrid;
layout(location = 8) flat in float vFadeShare;
layout(location = 9) flat in uint vBandStep;
layout(constant_id = 1) const bool kBlend = true;  // impostor-blend: two frames, or the nearest cell

void main() {
    const ImpostorBlend cells = ImpostorBlend(vCells, vBandStep, vWeights);
    if (impostorShadowTexelCoverage(atlasAlbedo, kBlend, cells, vGrid, vLocal) < 0.5) discard;
}
