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
#include "triangle_coverage.glsl.inc"

layout(local_size_x = MESH_RASTER_WORKGROUP) in;

layout(std430, set = 0, binding = 0) readonly buffer Draws { DrawIndexedCommand draws[]; };
layout(std430, set = 0, binding = 1) readonly buffer Split { MeshSplit split; };
layout(std430, set = 0, binding = 2) readonly buffer Listed { uint listed[]; };
layout(std430, set = 0, binding = 3) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 4) readonly buffer Positions { vec4 positions[]; };  // skinned, world space
layout(std430, set = 0, binding = 5) buffer Visibility { uint64_t visibility[]; };

layout(push_constant) uniform Push { MeshRasterPush push; };

// Where a skinned vertex falls on screen: x, y in pixels (y down, snapped), z the depth.
vec3 toScreen(uint vertex) {
    const vec4 clip = push.viewProjection * vec4(positions[vertex].xyz, 1.0);
    const vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * push.viewport.xy;
    return vec3(round(pixel * kSubPixel) / kSubPixel, clip.z / clip.w);
}

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
    const vec3 swapped = p1;
    p1 = p2, p2 = swapped;
    const TriangleCoverage t = triangleCoverage(p0.xy, p1.xy, p2.xy, ivec2(push.viewport.xy));
    if (any(greaterThan(t.first, t.last))) return;
    const vec2 slopes = triangleDepthSlopes(p0, p1, p2, -area);
    for (int y = t.first.y; y <= t.last.y; ++y) {
        for (int x = t.first.x; x <= t.last.x; ++x) {
            if (!triangleCovers(t, x, y)) continue;
            const float z = p0.z + slopes.x * (float(x) + 0.5 - p0.x) + slopes.y * (float(y) + 0.5 - p0.y);
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
