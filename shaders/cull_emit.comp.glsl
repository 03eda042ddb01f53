#version 460
#extension GL_GOOGLE_include_directive : require
// After the prefix sums: one indexed draw per visible character, compacted for
// vkCmdDrawIndexedIndirectCount, drawing its LOD's index range from its skinned vertices;
// firstInstance carries the character to the shaders. For the vertex-shader baseline, the same draw
// from the bind pose in the character's own slot (culled characters' slots stay zeroed).
//
// The shadow pass's draws come from the same skinned vertices: a caster draws its shadow level's index
// range, a prefix of its skinned level's vertices (cull.glsl.inc, shadowState), appended after the
// colour draws in any order (a depth-only pass does not depend on it). A character skinned only for
// its shadow (out of view) keeps its colour draw with no instance, so the colour pass skips it.
//
// Bone blocks per mesh slot (render/crowd_buffers.h, BoneBlocks): draw i's character owns bone block i
// this frame, and its record's ids.y says so, for the palette pass that writes the block and every
// skinning method that reads it (they run after this pass). Characters not listed keep a stale ids.y
// that nothing reads.
//
// A character in view fading to the next mesh level (gpu_types.h, FADE_SHIFT) is drawn as any other:
// skinning morphs it (shaders/lod_morph.glsl.inc); it is only counted. One fading into its impostor
// is drawn from a list of its own (after the shadow draws), dithered on its mesh's share of its
// pixels; the cull pass listed it as an impostor too.
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push {
    uint fixedLayout;       // 1: every character has its own skinned slot (the static method)
    uint characterDrawsOn;  // 1: write the per-character draws too
    uint shadowDrawBase;    // where the shadow draws start in `draws` (its colour draws' capacity)
    uint slotBoneRows;      // BoneRows per mesh slot's bone block; 0: blocks per character (ids.y fixed)
    uint fadingDrawBase;    // where the draws of those fading into impostors start in `draws` (after the shadow draws)
};
layout(std430, set = 0, binding = 0) readonly buffer Cull { CullUniforms cull; };  // not a uniform buffer (gpu_types.h)
layout(std430, set = 0, binding = 2) buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 3) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 4) readonly buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 5) readonly buffer Visible { uint visible[]; };
layout(std430, set = 0, binding = 7) buffer Totals { DrawTotals totals; };
layout(std430, set = 0, binding = 10) writeonly buffer Draws { DrawIndexedCommand draws[]; };
layout(std430, set = 0, binding = 11) writeonly buffer CharacterDraws { DrawIndexedCommand characterDraws[]; };
layout(std430, set = 0, binding = 17) readonly buffer ShadowStates { uint shadowStates[]; };

void main() {
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < totals.drawCount; i += stride) {
        // The bucket holding draw i: the last whose first draw is at or before i (empty buckets share
        // their successor's base and are stepped over).
        uint b = 0u;
        while (b + 1u < cull.flags.w && frames[b + 1u].drawBase <= i) ++b;
        BucketRecord bucket = buckets[b];
        uint k = i - frames[b].drawBase;
        uint c = visible[bucket.list.z + k];
        uint shadow = shadowStates[c];
        uint inView = (shadow & SHADOW_IN_VIEW_BIT) != 0u ? 1u : 0u;
        bool casts = (shadow & SHADOW_CASTS_BIT) != 0u;
        BucketRecord shadowBucket = buckets[b - bucket.list.y + (shadow & SHADOW_LEVEL_MASK)];
        uint vertexOffset = fixedLayout != 0u ? bucket.fixedLayout.x + characters[c].ids.z * bucket.mesh.z
                                              : frames[b].vertexBase + k * bucket.mesh.z;
        // Fading (in view, within a fade band): into its coarser mesh level (morphed, drawn as the
        // others), or from its last mesh level into its impostor.
        bool fading = inView != 0u && (shadow >> FADE_SHIFT) != 0u;
        bool intoImpostor = fading && bucket.list.y + 1u == LOD_COUNT;
        draws[i] = DrawIndexedCommand(bucket.mesh.y, intoImpostor ? 0u : inView, bucket.mesh.x, int(vertexOffset), c);
        if (slotBoneRows != 0u) characters[c].ids.y = i * slotBoneRows;
        // Its colour draw is listed apart for the pipeline that dithers, and has no instance in
        // draws[i]: the colour pass draws everyone else with the pipeline that does not discard and so
        // keeps the early depth test (a vertex shader skipping them instead cost the vertex-bound
        // frames more than it saved: docs/picture-quality.md).
        if (intoImpostor)
            draws[fadingDrawBase + atomicAdd(totals.fading.x, 1u)] =
                DrawIndexedCommand(bucket.mesh.y, 1u, bucket.mesh.x, int(vertexOffset), c);
        else if (fading)
            atomicAdd(totals.morphCount, 1u);
        if (casts)
            draws[shadowDrawBase + atomicAdd(totals.shadowDrawCount, 1u)] =
                DrawIndexedCommand(shadowBucket.mesh.y, 1u, shadowBucket.mesh.x, int(vertexOffset), c);
        if (characterDrawsOn != 0u) {
            characterDraws[c] = DrawIndexedCommand(bucket.mesh.y, inView, bucket.mesh.x, int(bucket.mesh.w), c);
            characterDraws[cull.flags.x + c] = DrawIndexedCommand(shadowBucket.mesh.y, casts ? 1u : 0u,
                                                                  shadowBucket.mesh.x, int(bucket.mesh.w), c);
        }
    }
}
