#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1, the paper's idea: skinning in a fragment shader. Each texel of the RGBA32F targets is one
// (character, vertex); the fragment skins that vertex with that character's bones and writes the
// world-space position and normal, which a copy then turns into the draw pass's vertex buffer.
#include "gpu_types.h"
#include "skinning.glsl.inc"

layout(push_constant) uniform Push { SkinPassParams params; };
layout(std430, set = 0, binding = 0) readonly buffer BindPose { SkinVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bones { BoneRows bones[]; };
layout(std430, set = 0, binding = 4) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 5) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 6) readonly buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 7) readonly buffer List { uint list[]; };
layout(std430, set = 0, binding = 8) readonly buffer States { uint states[]; };  // gpu_types.h, FADE_SHIFT
layout(std430, set = 0, binding = 9) readonly buffer MorphTargets { LodMorphTarget morphTargets[]; };
#include "skin_texel.glsl.inc"
#define LOD_MORPH_BONE(i) bones[i]
#include "lod_morph.glsl.inc"
// 1: this pipeline draws the rectangles of buckets whose characters may morph into a coarser mesh
// level; 0 (the last level): the morph's code is left out.
layout(constant_id = 0) const uint kMorphs = 1u;

layout(location = 0) flat in uint inBucket;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

void main() {
    TexelVertex tv;
    // A neighbouring bucket's texel: leave it to that bucket's rectangle.
    if (!texelVertex(inBucket, uvec2(gl_FragCoord.xy), tv)) discard;
    SkinVertex v = vertices[tv.vertex];
    Skinned s = skinVertex(v, bones[tv.boneBase + v.joints.x], bones[tv.boneBase + v.joints.y],
                           bones[tv.boneBase + v.joints.z], bones[tv.boneBase + v.joints.w]);
    // A character fading into its coarser mesh level: the vertices it drops move toward it.
    if (kMorphs != 0u) s = lodMorphedVertex(s, inBucket, tv.vertex, tv.character, tv.boneBase);
    outPosition = vec4(s.position, 1.0);
    outNormal = vec4(s.normal, v.normal.w);
}
