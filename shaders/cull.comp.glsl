#version 460
#extension GL_GOOGLE_include_directive : require
// The cull pass (niagara's drawcull): one thread per character tests its pose sphere against the
// view frustum, picks its level of detail with hysteresis, and appends it to the visible list of
// its (model, LOD) bucket. The CPU never sees per-character visibility.
#include "gpu_types.h"
#include "cull.glsl.inc"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = 0) readonly buffer Cull { CullUniforms cull; };  // not a uniform buffer (gpu_types.h)
layout(std430, set = 0, binding = 1) readonly buffer Models { ModelRecord models[]; };
layout(std430, set = 0, binding = 2) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 3) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 4) buffer Frames { BucketFrame frames[]; };
layout(std430, set = 0, binding = 5) writeonly buffer Visible { uint visible[]; };
layout(std430, set = 0, binding = 6) buffer LodState { uint lodState[]; };
layout(std430, set = 0, binding = 12) buffer Impostors { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 13) writeonly buffer ImpostorList { uint impostors[]; };

// Impostors cast no shadow (they are not drawn into the shadow map), so only those in view are kept.
void appendImpostor(uint c, vec4 sphere) {
    if (cull.flags.y != 0u && !sphereInFrustum(cull.planes, sphere)) return;
    impostors[atomicAdd(impostorFrame.count, 1u)] = c;
}

void cullCharacter(uint c) {
    CharacterRecord character = characters[c];
    vec4 sphere = worldSphere(character, models[character.ids.x]);
    bool inView = cull.flags.y == 0u ||
                  (cull.limits.y != 0u ? casterInFrustum(cull.planes, sphere, cull.light.xyz)
                                       : sphereInFrustum(cull.planes, sphere));
    // Every character's level is kept up to date, visible or not, so culling never changes a level.
    uint lod = 0u;
    if (cull.flags.z != 0u) lod = chooseLod(projectedDiameter(sphere, cull.camera), lodState[c], cull.lod);
    lodState[c] = cull.flags.z != 0u ? lod + 1u : 0u;
    if (lod == IMPOSTOR_LEVEL) {
        appendImpostor(c, sphere);
        return;
    }
    if (!inView) return;
    // The mesh levels hold at most limits.z characters (their skinned vertices are sized for that);
    // the rest are drawn as impostors. Which ones is the order of the atomics: any, when over the cap.
    if (cull.limits.z != 0u && atomicAdd(impostorFrame.meshCount, 1u) >= cull.limits.z) {
        atomicAdd(impostorFrame.demoted, 1u);
        appendImpostor(c, sphere);
        return;
    }
    uint bucket = character.ids.x * LOD_COUNT + lod;
    uint slot = atomicAdd(frames[bucket].count, 1u);
    visible[buckets[bucket].list.z + slot] = c;
}

void main() {
    // A grid-stride loop: crowds past the dispatch limit (65,535 groups on some devices) take turns.
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint c = gl_GlobalInvocationID.x; c < cull.flags.x; c += stride) cullCharacter(c);
}
