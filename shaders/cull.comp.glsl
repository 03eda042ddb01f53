#version 460
#extension GL_GOOGLE_include_directive : require
// The cull pass (niagara's drawcull): one thread per character tests its pose sphere against the
// view frustum, picks its level of detail with hysteresis, and appends it to the visible list of
// its (model, LOD) bucket; with shadows, it decides whether and at which level the character casts
// (cull.glsl.inc, shadowState) and lists it among its shadow level's casters. The CPU never sees
// per-character visibility. With a mesh-level cap, a
// character that qualifies for a mesh level is listed as a candidate of the cut instead
// (mesh_cut.glsl.inc): which ones keep their meshes is known only once all are counted.
#include "gpu_types.h"
#include "cull.glsl.inc"
#include "cull_lists.glsl.inc"
#include "mesh_cut.glsl.inc"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(std430, set = 0, binding = 1) readonly buffer Models { ModelRecord models[]; };
layout(std430, set = 0, binding = 6) buffer LodState { uint lodState[]; };
layout(std430, set = 0, binding = 15) writeonly buffer Candidates { uvec2 candidates[]; };

void listMeshCandidate(uint c, float size, bool drawnIfDemoted) {
    uvec2 candidate = meshCandidate(c, size, drawnIfDemoted);
    candidates[atomicAdd(impostorFrame.meshCount, 1u)] = candidate;
    atomicAdd(meshCutWords[COARSE_HISTOGRAM + coarseBucketOf(candidateKey(candidate))], 1u);
}

// The shadow cascades whose volumes a sphere reaches, a bit each (gpu_types.h, SHADOW_CASCADE_SHIFT).
uint cascadesReached(vec4 sphere) {
    uint reached = 0u;
    for (uint k = 0u; k < cull.shadowFlags.z; ++k) {
        bool inside = true;
        for (uint i = 0u; i < 6u; ++i) {
            vec4 plane = cull.cascadePlanes[6u * k + i];
            inside = inside && dot(plane.xyz, sphere.xyz) + plane.w >= -sphere.w;
        }
        if (inside) reached |= 1u << k;
    }
    return reached;
}

void cullCharacter(uint c) {
    CharacterRecord character = characters[c];
    // A free slot (its scale 0, crowd/population.h): nothing to draw or cast; a character that takes
    // the slot chooses its level afresh.
    if (!(character.tint.w > 0.0)) {
        lodState[c] = 0u;
        shadowStates[c] = 0u;
        return;
    }
    vec4 sphere = worldSphere(character, models[character.ids.x]);
    bool inView = cull.flags.y == 0u || sphereInFrustum(cull.planes, sphere);
    float size = projectedDiameter(sphere, cull.camera);
    // Every character's level is kept up to date, visible or not, so culling never changes a level.
    uint lod = 0u;
    bool fades = cull.flags.z != 0u && cull.fade.x != 0u;
    if (cull.flags.z != 0u) lod = fades ? fadedLod(size, cull.lod) : chooseLod(size, lodState[c], cull.lod);
    lodState[c] = cull.flags.z != 0u ? lod + 1u : 0u;
    uint cascades = cull.limits.y != 0u ? cascadesReached(sphere) : 0u;
    float texelsPerUnit = cull.cascadeTexels[cascades != 0u ? findLSB(cascades) : 0];
    uint shadow = shadowState(sphere, lod, inView, cull.planes, cascades, texelsPerUnit, cull.light.xyz, cull.shadow,
                              cull.flags, cull.limits, cull.shadowFlags);
    if (fades) shadow |= fadeShare(size, lod, cull.lod) << FADE_SHIFT;
    shadowStates[c] = shadow;
    if (lod == IMPOSTOR_LEVEL) {
        placeImpostor(c, shadow);
        return;
    }
    if (!inView && (shadow & SHADOW_CASTS_BIT) == 0u) return;
    // The mesh levels hold at most limits.z characters (their skinned vertices are sized for that): the
    // cut keeps the largest on screen and demotes the rest, farthest first.
    if (cull.limits.z != 0u) {
        listMeshCandidate(c, size, inView);
        return;
    }
    placeMesh(c, lod, shadow);
}

void main() {
    // A grid-stride loop: crowds past the dispatch limit (65,535 groups on some devices) take turns.
    uint stride = gl_NumWorkGroups.x * CULL_WORKGROUP_SIZE;
    for (uint c = gl_GlobalInvocationID.x; c < cull.flags.x; c += stride) cullCharacter(c);
}
