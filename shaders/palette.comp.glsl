#version 460
#extension GL_GOOGLE_include_directive : require
// The palette pass: bone matrices for the characters culling listed in one (model, LOD) bucket,
// written where every skinning method reads them (CharacterRecord.ids.y). Characters off screen get
// none: their motion is a closed form (motion.comp), so nothing about them needs updating.
//
// One thread per (character, joint): a workgroup takes 64 / joints characters (one when a model has
// more than 64 joints). Each thread samples its joint's clip(s) at the character's synchronized phase
// and blends them into shared memory; then each composes its joint's chain of parents up to the root
// from there (no sweep over the hierarchy, no barrier per level), places it and applies its inverse
// bind matrix: bone = placement * root * local[root joint] * ... * local[j] * inverseBind[j].
#include "gpu_types.h"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push { PalettePush push; };
layout(std430, set = 0, binding = 0) readonly buffer Models { AnimationModel animModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Joints { AnimationJoint animJoints[]; };
layout(std430, set = 0, binding = 2) readonly buffer Clips { AnimationClip animClips[]; };
layout(std430, set = 0, binding = 3) readonly buffer Tracks { AnimationTrack animTracks[]; };
layout(std430, set = 0, binding = 4) readonly buffer Times { float keyTimes[]; };
layout(std430, set = 0, binding = 5) readonly buffer Values { vec4 keyValues[]; };
layout(std430, set = 0, binding = 6) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 7) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 8) readonly buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 9) readonly buffer Visible { uint visible[]; };
layout(std430, set = 0, binding = 10) writeonly buffer Bones { BoneRows bones[]; };

#include "animation.glsl.inc"

// Slots of shared memory: 64 for models of up to 64 joints (so it stays small and many workgroups
// share a multiprocessor), MAX_ANIMATION_JOINTS for larger ones (one character a workgroup).
layout(constant_id = 0) const uint SLOTS = 64;
shared BoneRows locals[SLOTS];

// Joint j's local transform for character `character` of `model`.
BoneRows localTransform(CharacterRecord character, AnimationModel model, uint j) {
    AnimationJoint rest = animJoints[model.info.x + j];
    if (model.info.w == 0u)
        return affineOf(JointPose(rest.restTranslation.xyz, normalize(rest.restRotation), rest.restScale.xyz));
    uint from = model.info.z + (character.ids.w & 0xFFFFu);
    uint to = model.info.z + (character.ids.w >> 16u);
    float cycle = fract(character.pose.x);  // both clips at the same point of their cycles
    float weight = character.pose.y;
    AnimationClip toClip = animClips[to];
    JointPose pose = sampleJoint(toClip.info.x, j, rest, wrapClipTime(cycle * toClip.timing.x, toClip.timing.x));
    if (weight < 1.0) {
        AnimationClip fromClip = animClips[from];
        JointPose fromPose = sampleJoint(fromClip.info.x, j, rest, wrapClipTime(cycle * fromClip.timing.x, fromClip.timing.x));
        pose = blendPoses(fromPose, pose, weight);
    }
    return affineOf(pose);
}

void main() {
    BucketRecord bucket = buckets[push.bucket.x];
    uint joints = push.bucket.y;
    uint perGroup = push.bucket.z;
    uint count = frames[push.bucket.x].count;
    AnimationModel model = animModels[bucket.list.x];
    uint slots = perGroup * joints;
    // A grid-stride loop over groups of characters; its bound is uniform, as barrier() needs.
    for (uint group = gl_WorkGroupID.x; group * perGroup < count; group += gl_NumWorkGroups.x) {
        uint first = group * perGroup;
        barrier();  // the previous turn is done reading `locals`
        for (uint i = gl_LocalInvocationIndex; i < slots; i += 64u) {
            uint k = first + i / joints;
            if (k < count) locals[i] = localTransform(characters[visible[bucket.list.z + k]], model, i % joints);
        }
        barrier();
        for (uint i = gl_LocalInvocationIndex; i < slots; i += 64u) {
            uint k = first + i / joints;
            if (k >= count) continue;
            uint j = i % joints;
            uint base = i - j;  // this character's first slot in `locals`
            CharacterRecord character = characters[visible[bucket.list.z + k]];
            BoneRows chain = locals[i];
            int parent = int(animJoints[model.info.x + j].restTranslation.w);
            while (parent >= 0) {
                chain = composeAffine(locals[base + uint(parent)], chain);
                parent = int(animJoints[model.info.x + uint(parent)].restTranslation.w);
            }
            BoneRows top = composeAffine(placementAffine(character.placement, character.tint.w), model.root);
            BoneRows world = composeAffine(top, chain);
            // A prop the character does not carry: collapsed to a point at its joint (anim/props_carried.h).
            uint prop = uint(animJoints[model.info.x + j].restScale.w);
            bool carried = prop == 0u || ((uint(character.pose.z) >> (prop - 1u)) & 1u) != 0u;
            bones[character.ids.y + j] = carried ? composeAffine(world, animJoints[model.info.x + j].inverseBind)
                                                 : BoneRows(vec4(0.0, 0.0, 0.0, world.row0.w), vec4(0.0, 0.0, 0.0, world.row1.w),
                                                            vec4(0.0, 0.0, 0.0, world.row2.w));
        }
    }
}
