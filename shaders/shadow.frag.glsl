#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow pass writes depth only: the rasterizer's depth is all it needs. It takes the character
// vertex shaders' outputs (unused) so that their interface matches without maintenance4.
#include "gpu_types.h"
#define VARYING in
#include "draw_varyings.glsl.inc"

void main() {}
