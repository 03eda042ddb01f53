#version 460
#extension GL_GOOGLE_include_directive : require
// "vs-instanced", the modern baseline: vertex-shader skinning with every character in one instanced
// draw; the instance index selects the character's bones in a storage buffer.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"
#include "skin_vs_common.glsl.inc"

layout(constant_id = 0) const uint BONE_STRIDE = 64;
layout(std430, set = 1, binding = 0) readonly buffer Bones { BoneRows bones[]; };

void main() {
    uint base = uint(gl_InstanceIndex) * BONE_STRIDE;
    emitSkinnedVertex(bones[base + inJoints.x], bones[base + inJoints.y], bones[base + inJoints.z],
                      bones[base + inJoints.w]);
}
