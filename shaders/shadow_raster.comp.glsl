#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow map's mesh casters rasterized in compute (docs/gpu-driven-frame.md, "Shadows in compute"):
// depth only, so a 32-bit atomic min of the depth's bits (non-negative floats order as their bits do)
// is the whole depth test. The hardware path draws the same commands through a small graphics slice;
// here every SM takes casters. One workgroup per caster draw of the shadow pass's compacted list (the
// command the hardware pass would draw: its level's index range and first skinned vertex), its
// threads over the draw's triangles, each triangle over the texel centres of its bounding box.
//
// Rules kept from the hardware pass, so the two maps agree texel for texel but for edge rounding:
// samples at texel centres; vertices snapped to 1/256 texel (the rasterizer's sub-pixel grid); the
// top-left rule on texel centres that lie on an edge; both faces; depth interpolated in the
// triangle's plane, clipped to [0, 1], biased as the hardware pass's pipeline is (1.0 x the minimum
// resolvable difference of the triangle's largest depth + 1.5 x its depth slope per texel), clamped.
#include "gpu_types.h"
#include "triangle_coverage.glsl.inc"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Draws { DrawIndexedCommand draws[]; };  // colour's, then shadow's
layout(std430, set = 0, binding = 1) readonly buffer Totals { DrawTotals totals; };
layout(std430, set = 0, binding = 2) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 3) readonly buffer Positions { vec4 positions[]; };  // skinned, world space
layout(std430, set = 0, binding = 4) buffer Depth { uint depth[]; };  // the map, row-major, float bits

layout(push_constant) uniform Push {
    mat4 lightViewProjection;
    uint size;         // texels per side
    uint groupsPerRow; // the dispatch's x: draw = y * groupsPerRow + x
    uint firstDraw;    // where the shadow pass's commands start in `draws` (DrawLists::drawCapacity)
} push;

const float kBiasConstant = 1.0;     // as the hardware pass's pipeline (render/character_draw.cpp)
const float kBiasSlope = 1.5;

// Where a skinned vertex falls in the map: x, y in texels (snapped), z the depth.
vec3 toMap(uint vertex) {
    const vec4 clip = push.lightViewProjection * vec4(positions[vertex].xyz, 1.0);  // orthographic: w = 1
    const vec2 texel = (clip.xy * 0.5 + 0.5) * float(push.size);
    return vec3(round(texel * kSubPixel) / kSubPixel, clip.z);
}

// The minimum resolvable difference of a D32_SFLOAT depth near z: one unit in the last place of the
// triangle's largest depth (Vulkan's r for floating-point depth).
float resolvable(float z) {
    int exponent;
    frexp(max(z, 1e-30), exponent);  // z = m * 2^exponent, m in [0.5, 1)
    return ldexp(1.0, exponent - 1 - 23);
}

void writeDepth(ivec2 texel, float z) {
    atomicMin(depth[uint(texel.y) * push.size + uint(texel.x)], floatBitsToUint(clamp(z, 0.0, 1.0)));
}

void rasterize(vec3 p0, vec3 p1, vec3 p2) {
    // Orient so the inside is positive (both faces cast).
    float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (area == 0.0) return;
    if (area < 0.0) {
        const vec3 t = p1;
        p1 = p2, p2 = t;
        area = -area;
    }
    const TriangleCoverage t = triangleCoverage(p0.xy, p1.xy, p2.xy, ivec2(int(push.size)));
    if (any(greaterThan(t.first, t.last))) return;
    const vec2 slopes = triangleDepthSlopes(p0, p1, p2, area);
    const float bias = kBiasConstant * resolvable(max(max(p0.z, p1.z), p2.z)) + kBiasSlope * max(abs(slopes.x), abs(slopes.y));
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
    const uint draw = gl_WorkGroupID.y * push.groupsPerRow + gl_WorkGroupID.x;
    if (draw >= totals.shadowDrawCount) return;
    const DrawIndexedCommand command = draws[push.firstDraw + draw];
    if (command.instanceCount == 0u) return;
    const uint triangles = command.indexCount / 3u;
    for (uint t = gl_LocalInvocationID.x; t < triangles; t += gl_WorkGroupSize.x) {
        const uint first = command.firstIndex + 3u * t;
        rasterize(toMap(uint(int(indices[first]) + command.vertexOffset)),
                  toMap(uint(int(indices[first + 1u]) + command.vertexOffset)),
                  toMap(uint(int(indices[first + 2u]) + command.vertexOffset)));
    }
}
