#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow map's mesh casters rasterized in compute (docs/gpu-driven-frame.md, "Shadows in compute"):
// depth only, so a 32-bit atomic min of the depth's bits (non-negative floats order as their bits do)
// is the whole depth test. The hardware path draws the same commands through a small graphics slice;
// here every SM takes casters. One workgroup per caster draw of the shadow pass's compacted list (the
// command the hardware pass would draw: its level's index range and first skinned vertex), its
// threads over the draw's triangles, each triangle over the texel centres of its bounding box. With
// shadow cascades, the dispatch's z is the cascade: a workgroup draws its caster into that cascade's
// square of the map (the square a scissor) if the cull pass set the cascade's bit in its state word
// (render/shadow_cascades.h). One dispatch for all: on the H100 a dispatch a cascade, each waiting for
// the last, put four slowest workgroups end to end (paper-fig4's shadow pass 0.35 -> 1.58 ms).
//
// Rules kept from the hardware pass, so the two maps agree texel for texel but for edge rounding:
// samples at texel centres; vertices snapped to 1/256 texel (the rasterizer's sub-pixel grid); the
// top-left rule on texel centres that lie on an edge; both faces; depth interpolated in the
// triangle's plane, clipped to [0, 1], biased as the hardware pass's pipeline is (1.0 x the map's
// minimum resolvable difference + 1.5 x the depth slope per texel), clamped. The depths stay floats
// here; shadow_pack.comp.glsl rounds them to the map's 16 bits as the hardware rounds its fragments'.
#include "gpu_types.h"
#include "triangle_coverage.glsl.inc"
#include "shadow_caster_rules.glsl.inc"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Draws { DrawIndexedCommand draws[]; };  // colour's, then shadow's
layout(std430, set = 0, binding = 1) readonly buffer Totals { DrawTotals totals; };
layout(std430, set = 0, binding = 2) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 3) readonly buffer Positions { vec4 positions[]; };  // skinned, world space
layout(std430, set = 0, binding = 4) buffer Depth { uint depth[]; };  // the map, row-major, float bits (then packed)
layout(std430, set = 0, binding = 5) readonly buffer ShadowStates { uint shadowStates[]; };  // per character

layout(push_constant) uniform Push {
    vec4 light[3];     // the first cascade's transform, rows x, y and depth: clip = row . (p, 1)
    // Each cascade's map texel x, y from the first's clip x, y: xy scale, zw offset (the cascades share
    // the light's view and depth and differ in extents only).
    vec4 toTexels[MAX_SHADOW_CASCADES];
    uvec4 sizes;       // x: texels per side, y: the dispatch's x (draw = y * this + x), z: where the shadow
                       // pass's commands start in `draws` (DrawLists::drawCapacity), w: cascades
} push;

// Where a skinned vertex falls in cascade c's square of the map: x, y in texels (snapped), z the depth.
vec3 toMap(uint vertex, uint c) {
    const vec4 p = vec4(positions[vertex].xyz, 1.0);
    const vec3 clip = vec3(dot(push.light[0], p), dot(push.light[1], p), dot(push.light[2], p));  // orthographic
    const vec2 texel = clip.xy * push.toTexels[c].xy + push.toTexels[c].zw;
    return vec3(round(texel * kSubPixel) / kSubPixel, clip.z);
}

void writeDepth(ivec2 texel, float z) {
    atomicMin(depth[uint(texel.y) * push.sizes.x + uint(texel.x)], floatBitsToUint(clamp(z, 0.0, 1.0)));
}

void rasterize(vec3 p0, vec3 p1, vec3 p2, ivec4 square) {
    // Orient so the inside is positive (both faces cast).
    float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (area == 0.0) return;
    if (area < 0.0) {
        const vec3 t = p1;
        p1 = p2, p2 = t;
        area = -area;
    }
    const TriangleCoverage t = triangleCoverageWithin(p0.xy, p1.xy, p2.xy, square.xy, square.zw);
    if (any(greaterThan(t.first, t.last))) return;
    const vec2 slopes = triangleDepthSlopes(p0, p1, p2, area);
    const float bias = shadowCasterBias(slopes);
    for (int y = t.first.y; y <= t.last.y; ++y) {
        for (int x = t.first.x; x <= t.last.x; ++x) {
            if (!triangleCovers(t, x, y)) continue;
            const float z = p0.z + slopes.x * (float(x) + 0.5 - p0.x) + slopes.y * (float(y) + 0.5 - p0.y);
            if (z < 0.0 || z > 1.0) continue;  // clipped by the near and far planes, as the hardware clips
            writeDepth(ivec2(x, y), z + bias);
        }
    }
}

void main() {
    const uint draw = gl_WorkGroupID.y * push.sizes.y + gl_WorkGroupID.x;
    const uint c = gl_WorkGroupID.z;
    if (draw >= totals.shadowDrawCount) return;
    const DrawIndexedCommand command = draws[push.sizes.z + draw];
    if (command.instanceCount == 0u || (shadowStates[command.firstInstance] & (1u << (SHADOW_CASCADE_SHIFT + c))) == 0u) return;
    const ivec4 square = shadowCascadeSquare(c, push.sizes.x, push.sizes.w);
    const uint triangles = command.indexCount / 3u;
    for (uint t = gl_LocalInvocationID.x; t < triangles; t += gl_WorkGroupSize.x) {
        const uint first = command.firstIndex + 3u * t;
        rasterize(toMap(uint(int(indices[first]) + command.vertexOffset), c),
                  toMap(uint(int(indices[first + 1u]) + command.vertexOffset), c),
                  toMap(uint(int(indices[first + 2u]) + command.vertexOffset), c), square);
    }
}
