#version 460
#extension GL_GOOGLE_include_directive : require
// An impostor's quad in the shadow map (depth only): the atlas texels the colour pass keeps (at least
// half coverage) cast, the rest do not. The coverage is blended over the same four cells as the colour
// pass's (impostor_sample.glsl.inc), so the shadow of a turning or walking character morphs with it
// rather than jumping a view or a frame on the ground; an alpha fetch costs little next to the quad's
// vertices, which bound this pass as they bound the colour pass.
#include "gpu_types.h"
#include "impostor_sample.glsl.inc"

layout(set = 2, binding = 0) uniform sampler2DArray atlasAlbedo;

layout(location = 0) in vec2 vLocal;
layout(location = 1) flat in uvec4 vCells;
// The colour pass's inputs, unused here: declared so the vertex shader's outputs all have a consumer.
layout(location = 2) flat in vec3 vTint;
layout(location = 3) flat in vec2 vHeading;
layout(location = 4) in vec3 vWorld;
layout(location = 5) flat in float vRadius;
layout(location = 6) flat in vec2 vWeights;
layout(location = 7) flat in uvec2 vGrid;

void main() {
    if (impostorBlendedTexel(atlasAlbedo, vCells, vWeights, vGrid, vLocal).a < 0.5) discard;
}
