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
// Large triangles are shared out: a thread that walks its triangle's texels alone is fine for a crowd,
// whose triangles cover a few texels each, but a map fitted to a few characters makes their triangles
// thousands of texels wide, and one thread walking them held the frame (the H100, 16 soldiers: a 4.8 ms
// shadow pass). So a triangle whose box holds more than kSmallTexels centres is listed instead: its box
// cut into kBlock x kBlock blocks, a record for each run of up to kBlocksPerRecord of them, and a second
// dispatch of this shader (kRecordPass) draws each record with a whole workgroup, a texel a thread,
// stepping over the blocks the triangle misses (a long thin triangle's box is mostly empty). Both draw
// a texel by the same rules from the same triangle, so the map is the same texel for texel whichever
// draws it. When the list is full the thread draws its triangle itself.
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
// The large triangles' records (cleared to a count of 0 each frame): x the shadow draw, y the triangle
// within it, z the cascade, w the record's first block (blocks numbered row by row over the box).
layout(std430, set = 0, binding = 6) buffer Records { uint recordCount; uint recordPad[3]; uvec4 records[]; };

// 0: one workgroup a caster draw, listing its large triangles; 1: one workgroup a record of blocks.
layout(constant_id = 0) const uint kRecordPass = 0u;
const int kSmallTexels = 64;        // a box of more texel centres than this is shared out
const int kBlock = 16;              // texels a side of a block
const uint kBlocksPerRecord = 64u;  // blocks a record (a workgroup's share: up to 16,384 texels)

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

// A triangle of the map ready to draw: its coverage (empty: first > last), the depth's plane and bias.
struct MapTriangle {
    TriangleCoverage coverage;
    vec3 p0;
    vec2 slopes;
    float bias;
};

MapTriangle mapTriangle(vec3 p0, vec3 p1, vec3 p2, ivec4 square) {
    MapTriangle m;
    // Orient so the inside is positive (both faces cast).
    float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (area < 0.0) {
        const vec3 t = p1;
        p1 = p2, p2 = t;
        area = -area;
    }
    m.coverage = triangleCoverageWithin(p0.xy, p1.xy, p2.xy, square.xy, square.zw);
    if (area == 0.0) m.coverage.last = m.coverage.first - 1;  // no inside: nothing to draw
    m.p0 = p0;
    m.slopes = area == 0.0 ? vec2(0.0) : triangleDepthSlopes(p0, p1, p2, area);
    m.bias = shadowCasterBias(m.slopes);
    return m;
}

void drawTexel(MapTriangle m, int x, int y) {
    if (!triangleCovers(m.coverage, x, y)) return;
    const float z = m.p0.z + m.slopes.x * (float(x) + 0.5 - m.p0.x) + m.slopes.y * (float(y) + 0.5 - m.p0.y);
    if (z < 0.0 || z > 1.0) return;  // clipped by the near and far planes, as the hardware clips
    writeDepth(ivec2(x, y), z + m.bias);
}

// Triangle t of the shadow draw `draw` (its command `command`) in cascade c's square.
MapTriangle drawTriangle(DrawIndexedCommand command, uint t, uint c) {
    const uint first = command.firstIndex + 3u * t;
    return mapTriangle(toMap(uint(int(indices[first]) + command.vertexOffset), c),
                       toMap(uint(int(indices[first + 1u]) + command.vertexOffset), c),
                       toMap(uint(int(indices[first + 2u]) + command.vertexOffset), c), shadowCascadeSquare(c, push.sizes.x, push.sizes.w));
}

ivec2 blocksOf(MapTriangle m) { return (m.coverage.last - m.coverage.first + kBlock) / kBlock; }

// Lists a large triangle's records for the second dispatch; false when the list has no room for them.
bool listRecords(MapTriangle m, uint draw, uint t, uint c) {
    const ivec2 blocks = blocksOf(m);
    const uint count = (uint(blocks.x * blocks.y) + kBlocksPerRecord - 1u) / kBlocksPerRecord;
    const uint at = atomicAdd(recordCount, count);
    if (at + count > uint(records.length())) return false;
    for (uint i = 0u; i < count; ++i) records[at + i] = uvec4(draw, t, c, i * kBlocksPerRecord);
    return true;
}

void drawCasters() {
    const uint draw = gl_WorkGroupID.y * push.sizes.y + gl_WorkGroupID.x;
    const uint c = gl_WorkGroupID.z;
    if (draw >= totals.shadowDrawCount) return;
    const DrawIndexedCommand command = draws[push.sizes.z + draw];
    if (command.instanceCount == 0u || (shadowStates[command.firstInstance] & (1u << (SHADOW_CASCADE_SHIFT + c))) == 0u) return;
    const uint triangles = command.indexCount / 3u;
    for (uint t = gl_LocalInvocationID.x; t < triangles; t += gl_WorkGroupSize.x) {
        const MapTriangle m = drawTriangle(command, t, c);
        const ivec2 box = m.coverage.last - m.coverage.first + 1;
        if (any(lessThanEqual(box, ivec2(0)))) continue;
        if (box.x * box.y > kSmallTexels && listRecords(m, draw, t, c)) continue;
        for (int y = m.coverage.first.y; y <= m.coverage.last.y; ++y)
            for (int x = m.coverage.first.x; x <= m.coverage.last.x; ++x) drawTexel(m, x, y);
    }
}

// Whether the triangle may cover a texel centre between `first` and `last`: false when all four corner
// centres lie outside one edge by more than a hundredth of a texel (an edge function is linear, so the
// corners bound it). Only a shortcut: the texels of a block it keeps are each tested exactly.
bool mayCover(MapTriangle m, ivec2 first, ivec2 last) {
    const vec2 lo = vec2(first) + 0.5, hi = vec2(last) + 0.5;
    const vec2 a[3] = vec2[3](m.coverage.p1, m.coverage.p2, m.coverage.p0);
    const vec2 b[3] = vec2[3](m.coverage.p2, m.coverage.p0, m.coverage.p1);
    for (int e = 0; e < 3; ++e) {
        const vec2 d = b[e] - a[e];
        const vec2 gradient = vec2(-d.y, d.x);  // of the edge function w(s) = d.x (s.y - a.y) - d.y (s.x - a.x)
        const float best = d.x * ((gradient.y > 0.0 ? hi.y : lo.y) - a[e].y) - d.y * ((gradient.x > 0.0 ? hi.x : lo.x) - a[e].x);
        if (best < -0.01 * length(d)) return false;
    }
    return true;
}

// A fixed grid of workgroups takes the listed records in turn, its threads over each block's texels.
void drawRecords() {
    const uint listed = min(recordCount, uint(records.length()));
    for (uint i = gl_WorkGroupID.x; i < listed; i += gl_NumWorkGroups.x) {
        const uvec4 record = records[i];
        const MapTriangle m = drawTriangle(draws[push.sizes.z + record.x], record.y, record.z);
        const ivec2 blocks = blocksOf(m);
        const uint end = min(record.w + kBlocksPerRecord, uint(blocks.x * blocks.y));
        for (uint block = record.w; block < end; ++block) {
            const ivec2 first = m.coverage.first + ivec2(block % uint(blocks.x), block / uint(blocks.x)) * kBlock;
            const ivec2 last = min(first + kBlock - 1, m.coverage.last);
            if (!mayCover(m, first, last)) continue;
            const ivec2 size = last - first + 1;
            for (int k = int(gl_LocalInvocationID.x); k < size.x * size.y; k += int(gl_WorkGroupSize.x))
                drawTexel(m, first.x + k % size.x, first.y + k / size.x);
        }
    }
}

void main() {
    if (kRecordPass == 0u)
        drawCasters();
    else
        drawRecords();
}
