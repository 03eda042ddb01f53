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

const float kSubTexel = 256.0;       // the snapping grid
const float kBiasConstant = 1.0;     // as the hardware pass's pipeline (render/character_draw.cpp)
const float kBiasSlope = 1.5;
const int kExactExtent = 100;        // texels: up to it the edge tests are exact in 32-bit integers

// Where a skinned vertex falls in the map: x, y in texels (snapped), z the depth.
vec3 toMap(uint vertex) {
    const vec4 clip = push.lightViewProjection * vec4(positions[vertex].xyz, 1.0);  // orthographic: w = 1
    const vec2 texel = (clip.xy * 0.5 + 0.5) * float(push.size);
    return vec3(round(texel * kSubTexel) / kSubTexel, clip.z);
}

// Top-left rule for an edge a -> b of a triangle whose inside is where the edge function is positive
// (framebuffer coordinates, y down): a top edge runs exactly along x to +x, a left edge runs up.
bool topLeft(vec2 a, vec2 b) { return (a.y == b.y && b.x > a.x) || b.y < a.y; }

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
    const vec2 lo = min(min(p0.xy, p1.xy), p2.xy), hi = max(max(p0.xy, p1.xy), p2.xy);
    // Texel centres k + 0.5 inside [lo, hi], within the map.
    const ivec2 first = max(ivec2(ceil(lo - 0.5)), ivec2(0));
    const ivec2 last = min(ivec2(floor(hi - 0.5)), ivec2(int(push.size) - 1));
    if (any(greaterThan(first, last))) return;
    // Depth's plane: z = z0 + dzdx (x - x0) + dzdy (y - y0).
    const vec2 e1 = p1.xy - p0.xy, e2 = p2.xy - p0.xy;
    const float dzdx = ((p1.z - p0.z) * e2.y - (p2.z - p0.z) * e1.y) / area;
    const float dzdy = ((p2.z - p0.z) * e1.x - (p1.z - p0.z) * e2.x) / area;
    const float bias = kBiasConstant * resolvable(max(max(p0.z, p1.z), p2.z)) + kBiasSlope * max(abs(dzdx), abs(dzdy));
    const bool tl0 = topLeft(p1.xy, p2.xy), tl1 = topLeft(p2.xy, p0.xy), tl2 = topLeft(p0.xy, p1.xy);
    const bool exact = all(lessThanEqual(last - first, ivec2(kExactExtent)));
    // Exact edge functions: sub-texel integers relative to the box's first centre, whose products fit
    // in 32 bits for a box of up to 100 texels; a larger triangle (rare in a crowd's map) tests in float.
    const vec2 origin = vec2(first) + 0.5;
    const ivec2 q0 = ivec2(round((p0.xy - origin) * kSubTexel)), q1 = ivec2(round((p1.xy - origin) * kSubTexel)),
                q2 = ivec2(round((p2.xy - origin) * kSubTexel));
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            bool inside;
            if (exact) {
                const ivec2 s = (ivec2(x, y) - first) * int(kSubTexel);
                const int w0 = (q2.x - q1.x) * (s.y - q1.y) - (q2.y - q1.y) * (s.x - q1.x);
                const int w1 = (q0.x - q2.x) * (s.y - q2.y) - (q0.y - q2.y) * (s.x - q2.x);
                const int w2 = (q1.x - q0.x) * (s.y - q0.y) - (q1.y - q0.y) * (s.x - q0.x);
                inside = (w0 > 0 || (w0 == 0 && tl0)) && (w1 > 0 || (w1 == 0 && tl1)) && (w2 > 0 || (w2 == 0 && tl2));
            } else {
                const vec2 s = vec2(x, y) + 0.5;
                const float w0 = (p2.x - p1.x) * (s.y - p1.y) - (p2.y - p1.y) * (s.x - p1.x);
                const float w1 = (p0.x - p2.x) * (s.y - p2.y) - (p0.y - p2.y) * (s.x - p2.x);
                const float w2 = (p1.x - p0.x) * (s.y - p0.y) - (p1.y - p0.y) * (s.x - p0.x);
                inside = (w0 > 0.0 || (w0 == 0.0 && tl0)) && (w1 > 0.0 || (w1 == 0.0 && tl1)) &&
                         (w2 > 0.0 || (w2 == 0.0 && tl2));
            }
            if (!inside) continue;
            const float z = p0.z + dzdx * (float(x) + 0.5 - p0.x) + dzdy * (float(y) + 0.5 - p0.y);
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
