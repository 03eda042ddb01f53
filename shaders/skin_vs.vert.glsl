#version 460
#extension GL_GOOGLE_include_directive : require
// The paper's baseline: skinning in the vertex shader, one draw per character with its bones bound
// at a dynamic uniform-buffer offset (the paper's constant registers). firstInstance is the character.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"
#include "crowd_set.glsl.inc"
#define VARYING out
#include "draw_varyings.glsl.inc"
#include "skin_vs_common.glsl.inc"

layout(constant_id = 0) const uint BONE_COUNT = 64;
layout(std140, set = 2, binding = 0) uniform CharacterBones { BoneRows blockBones[BONE_COUNT]; };

void main() {
    emitSkinnedVertex(uint(gl_InstanceIndex), blockBones[inJoints.x], blockBones[inJoints.y],
                      blockBones[inJoints.z], blockBones[inJoints.w]);
}
