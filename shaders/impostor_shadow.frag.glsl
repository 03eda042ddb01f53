#version 460
#extension GL_GOOGLE_include_directive : require
// An impostor's quad in the shadow map (depth only): the atlas texels the colour pass keeps (at least
// half coverage) cast, the rest do not.
#include "gpu_types.h"

layout(set = 2, binding = 0) uniform sampler2DArray atlasAlbedo;

layout(location = 0) in vec2 vUv;
layout(location = 1) flat in uint vLayer;
// The colour pass's inputs, unused here: declared so the vertex shader's outputs all have a consumer.
layout(location = 2) flat in vec3 vTint;
layout(location = 3) flat in vec2 vHeading;
layout(location = 4) in vec3 vWorld;
layout(location = 5) flat in float vRadius;

void main() {
    if (texture(atlasAlbedo, vec3(vUv, float(vLayer))).a < 0.5) discard;
}
