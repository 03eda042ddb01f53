#version 460
#extension GL_GOOGLE_include_directive : require
// The impostor-level shadow casters rasterized in compute (render/impostor_shadow_raster.h), into the
// same buffer of depth bits as the mesh casters (shadow_raster.comp.glsl) before it is packed into the
// map. The hardware path draws each caster as a quad facing the light (impostor.vert.glsl with
// SHADOW_PASS) whose fragments keep the atlas texels of at least half coverage
// (impostor_shadow.frag.glsl); at eye level inside a crowd those quads cover hundreds of texels each
// and the graphics slice shades them all. Here each workgroup takes casters in turn, its threads over
// the texel centres of the caster's square as the map sees it, with the same quad (impostorQuad), the
// same cells and coverage, the same gradients for the atlas's mip level as the hardware's 2x2 texel
// quads derive (the quad's place in its cell is affine in the texel), and the same depth bias.
// The dispatch's z is the cascade: a caster is drawn into every cascade's square it reaches, as the
// hardware pass draws every caster with each square as its scissor.
#include "gpu_types.h"
#include "impostor_pose.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_quad.glsl.inc"
// The atlas read with this caster's gradients: one texel of the map's step in the atlas.
vec2 fetchDx, fetchDy;
#define IMPOSTOR_FETCH(atlas, coordinate) textureGrad(atlas, coordinate, fetchDx, fetchDy)
#include "impostor_sample.glsl.inc"

layout(local_size_x = 64) in;

// The frame's light and map, as the mesh casters' pass has them in its push constants.
struct ImpostorShadowFrame {
    vec4 light[3];                         // the first cascade's transform, rows x, y and depth
    vec4 toTexels[MAX_SHADOW_CASCADES];    // each cascade's texel x, y from the first's clip x, y
    vec4 lightDirection;                   // xyz: towards the sun (the quads face it)
    uvec4 sizes;                           // x: texels a side, y: where the casters start in the list,
                                           // z: cascades, w: 1 to blend two frames (impostor-blend)
};

layout(std430, set = 0, binding = 0) readonly buffer ImpostorModels { ImpostorModel impostorModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 2) readonly buffer Impostors { uint impostors[]; };
layout(std430, set = 0, binding = 3) readonly buffer Frame { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 4) buffer Depth { uint depth[]; };  // the map, row-major, float bits
layout(std430, set = 0, binding = 5) readonly buffer Params { ImpostorShadowFrame frame; };
layout(set = 1, binding = 0) uniform sampler2DArray atlasAlbedo;
#include "impostor_prop_set.glsl.inc"
#include "shadow_caster_rules.glsl.inc"

// A world point in cascade c's texels (xy) and the map's depth (z); a world vector the same way.
vec3 toMap(vec3 p, uint c) {
    const vec4 h = vec4(p, 1.0);
    const vec2 clip = vec2(dot(frame.light[0], h), dot(frame.light[1], h));
    return vec3(clip * frame.toTexels[c].xy + frame.toTexels[c].zw, dot(frame.light[2], h));
}
vec3 toMapVector(vec3 v, uint c) {
    return vec3(vec2(dot(frame.light[0].xyz, v), dot(frame.light[1].xyz, v)) * frame.toTexels[c].xy, dot(frame.light[2].xyz, v));
}

void writeDepth(ivec2 texel, float z) {
    atomicMin(depth[uint(texel.y) * frame.sizes.x + uint(texel.x)], floatBitsToUint(clamp(z, 0.0, 1.0)));
}

void main() {
    const uint c = gl_WorkGroupID.z;
    const ivec4 square = shadowCascadeSquare(c, frame.sizes.x, frame.sizes.z);
    const bool blend = frame.sizes.w != 0u;
    // Fewer casters than workgroups (a small group far off, the map fitted to it: each quad may cover
    // hundreds of thousands of texels) share each caster among `share` workgroups, each taking every
    // share-th run of 64 texels; on the H100 one workgroup a caster left 16 casters' pass 10 ms long
    // on 16 SMs. With as many casters as workgroups or more, a workgroup takes whole casters in turn.
    const uint casters = impostorFrame.shadowCount;
    const uint share = casters >= gl_NumWorkGroups.x ? 1u : gl_NumWorkGroups.x / max(casters, 1u);
    const uint slice = gl_WorkGroupID.x % share;
    for (uint i = gl_WorkGroupID.x / share; i < casters; i += gl_NumWorkGroups.x / share) {
        const CharacterRecord character = characters[impostors[frame.sizes.y + i]];
        ImpostorQuad q = impostorQuad(character, impostorModelOf(character), vec3(0.0), true, frame.lightDirection.xyz);
        q.blend = blend ? impostorNearestBand(q.blend) : impostorNearest(q.blend);
        // The quad in texels: centre + cx * r + cy * u for (cx, cy) in [-1, 1]^2.
        const vec3 centre = toMap(q.centre, c);
        const vec3 r = toMapVector(q.right * q.halfSide, c), u = toMapVector(q.up * q.halfSide, c);
        const float det = r.x * u.y - u.x * r.y;
        const vec2 reach = abs(r.xy) + abs(u.xy);
        const ivec2 first = max(ivec2(ceil(centre.xy - reach - 0.5)), square.xy);
        const ivec2 last = min(ivec2(floor(centre.xy + reach - 0.5)), square.zw);
        if (abs(det) < 1e-12 || any(greaterThan(first, last))) continue;
        // (cx, cy) from a texel centre, their steps a texel, and so the cell's and the atlas's.
        const vec2 cxStep = vec2(u.y, -u.x) / det, cyStep = vec2(-r.y, r.x) / det;
        fetchDx = vec2(0.5 * cxStep.x, -0.5 * cyStep.x) / float(q.grid.x);
        fetchDy = vec2(0.5 * cxStep.y, -0.5 * cyStep.y) / float(q.grid.x);
        const vec2 zStep = r.z * cxStep + u.z * cyStep;
        const float bias = shadowCasterBias(zStep);
        const uint width = uint(last.x - first.x + 1);
        const uint texels = width * uint(last.y - first.y + 1);
        for (uint t = slice * gl_WorkGroupSize.x + gl_LocalInvocationID.x; t < texels; t += share * gl_WorkGroupSize.x) {
            const ivec2 texel = first + ivec2(t % width, t / width);
            const vec2 d = vec2(texel) + 0.5 - centre.xy;
            const vec2 corner = vec2(dot(cxStep, d), dot(cyStep, d));
            if (any(greaterThan(abs(corner), vec2(1.0)))) continue;
            const float z = centre.z + corner.x * r.z + corner.y * u.z;
            if (z < 0.0 || z > 1.0) continue;  // clipped by the near and far planes, as the hardware clips
            if (impostorShadowTexelCoverage(atlasAlbedo, blend, q.blend, q.grid, impostorLocal(corner)) < 0.5) continue;
            writeDepth(texel, z + bias);
        }
    }
}
