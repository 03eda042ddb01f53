#version 460
#extension GL_GOOGLE_include_directive : require
// The paper's baseline: skinning in the vertex shader, each character's bones bound per draw
// (a dynamic uniform-buffer offset plays the part of the paper's constant registers).
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"
#include "skin_vs_common.glsl.inc"

layout(constant_id = 0) const uint BONE_COUNT = 64;
layout(std140, set = 1, binding = 0) uniform CharacterBones { BoneRows bones[BONE_COUNT]; };

void main() {
    emitSkinnedVertex(bones[inJoints.x], bones[inJoints.y], bones[inJoints.z], bones[inJoints.w]);
}
