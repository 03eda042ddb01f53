#version 460
#extension GL_GOOGLE_include_directive : require
// "vs-instanced", the modern baseline: vertex-shader skinning, one instanced draw per (model, LOD)
// bucket. firstInstance is the bucket's first entry in the visible list, so the instance index
// finds the character, and the character its bones.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"
#include "crowd_set.glsl.inc"
#define VARYING out
#include "draw_varyings.glsl.inc"
#include "skin_vs_common.glsl.inc"

void main() {
    uint c = visible[gl_InstanceIndex];
    uint base = characters[c].ids.y;
    emitSkinnedVertex(c, bones[base + inJoints.x], bones[base + inJoints.y], bones[base + inJoints.z],
                      bones[base + inJoints.w]);
}
