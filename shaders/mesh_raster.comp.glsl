#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// Small characters' skinned triangles rasterized in compute (docs/compute-raster.md, "Meshes"): a
// workgroup per character of the mesh-raster list (mesh_raster_split.comp.glsl), striding, its threads
// over the character's colour command's triangles (its level's index range, its skinned vertices),
// each triangle over the pixel centres of its bounding box, kept by a 64-bit atomic min of
// (depth bits, id) in the visibility buffer. The hardware's rules, so the two paths cover the same
// pixels: samples at pixel centres, vertices snapped to 1/256 pixel, the top-left rule, back faces
// culled as the colour pipeline culls them (counter-clockwise front faces), depth interpolated
// linearly in screen space (z/w, as the hardware does) and pixels outside depth [0, 1] dropped.
#include "gpu_types.h"

layout(local_size_x = MESH_RASTER_WORKGROUP) in;

layout(std430, set = 0, binding = 0) readonly buffer Draws { DrawIndexedCommand draws[]; };
layout(std430, set = 0, binding = 1) readonly buffer Split { MeshSplit split; };
layout(std430, set = 0, binding = 2) readonly buffer Listed { uint listed[]; };
layout(std430, set = 0, binding = 3) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 4) readonly buffer Positions { vec4 positions[]; };  // skinned, world space
layout(std430, set = 0, binding = 5) buffer Visibility { uint64_t visibility[]; };

layout(push_constant) uniform Push { MeshRasterPush push; };

const float kSubPixel = 256.0;  // the snapping grid
const int kExactExtent = 100;   // pixels: up to it the edge tests are exact in 32-bit integers

// Where a skinned vertex falls on screen: x, y in pixels (y down, snapped), z the depth.
vec3 toScreen(uint vertex) {
    const vec4 clip = push.viewProjection * vec4(positions[vertex].xyz, 1.0);
    const vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * push.viewport.xy;
    return vec3(round(pixel * kSubPixel) / kSubPixel, clip.z / clip.w);
}

// Top-left rule for an edge a -> b of a triangle whose inside is where the edge function is positive
// (framebuffer coordinates, y down): a top edge runs exactly along x to +x, a left edge runs up.
bool topLeft(vec2 a, vec2 b) { return (a.y == b.y && b.x > a.x) || b.y < a.y; }

void keep(ivec2 pixel, float z, uint id) {
    const uint64_t word = (uint64_t(floatBitsToUint(z)) << 32) | uint64_t(id);
    atomicMin(visibility[uint(pixel.y) * uint(push.viewport.x) + uint(pixel.x)], word);
}

void rasterize(vec3 p0, vec3 p1, vec3 p2, uint id) {
    // Twice the signed area in framebuffer coordinates: Vulkan's counter-clockwise front face is a
    // negative one here (its area has the opposite sign), and the colour pipeline culls back faces.
    const float area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (area >= 0.0) return;
    // Orient so the inside is positive.
    const vec3 t = p1;
    p1 = p2, p2 = t;
    const vec2 lo = min(min(p0.xy, p1.xy), p2.xy), hi = max(max(p0.xy, p1.xy), p2.xy);
    const ivec2 first = max(ivec2(ceil(lo - 0.5)), ivec2(0));
    const ivec2 last = min(ivec2(floor(hi - 0.5)), ivec2(push.viewport.xy) - 1);
    if (any(greaterThan(first, last))) return;
    const vec2 e1 = p1.xy - p0.xy, e2 = p2.xy - p0.xy;
    const float dzdx = ((p1.z - p0.z) * e2.y - (p2.z - p0.z) * e1.y) / -area;
    const float dzdy = ((p2.z - p0.z) * e1.x - (p1.z - p0.z) * e2.x) / -area;
    const bool tl0 = topLeft(p1.xy, p2.xy), tl1 = topLeft(p2.xy, p0.xy), tl2 = topLeft(p0.xy, p1.xy);
    const bool exact = all(lessThanEqual(last - first, ivec2(kExactExtent)));
    const vec2 origin = vec2(first) + 0.5;
    const ivec2 q0 = ivec2(round((p0.xy - origin) * kSubPixel)), q1 = ivec2(round((p1.xy - origin) * kSubPixel)),
                q2 = ivec2(round((p2.xy - origin) * kSubPixel));
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            bool inside;
            if (exact) {
                const ivec2 s = (ivec2(x, y) - first) * int(kSubPixel);
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
            if (z < 0.0 || z > 1.0) continue;  // the near and far planes clip it on the hardware
            keep(ivec2(x, y), z, id);
        }
    }
}

void main() {
    const uint count = min(split.computeCount, push.limits.y);
    for (uint place = gl_WorkGroupID.x; place < count; place += push.limits.w) {
        const DrawIndexedCommand command = draws[listed[place]];
        const uint triangles = command.indexCount / 3u;
        for (uint t = gl_LocalInvocationID.x; t < triangles; t += gl_WorkGroupSize.x) {
            const uint first = command.firstIndex + 3u * t;
            rasterize(toScreen(uint(int(indices[first]) + command.vertexOffset)),
                      toScreen(uint(int(indices[first + 1u]) + command.vertexOffset)),
                      toScreen(uint(int(indices[first + 2u]) + command.vertexOffset)),
                      MESH_RASTER_ID_BIT | (place << push.limits.x) | t);
        }
    }
}
