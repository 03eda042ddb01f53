#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Lists the screen tiles of a visibility buffer that hold any drawn pixel (render/visibility_tiles.h,
// docs/compute-raster.md): a workgroup a tile, its threads over the tile's pixels, and one append per
// covered tile, which counts the resolve's instances. Reading the buffer once in compute is far cheaper
// than a fragment invocation for every pixel of the screen.
#include "gpu_types.h"

layout(local_size_x = VISIBILITY_TILE_GROUP, local_size_y = VISIBILITY_TILE_GROUP) in;
layout(constant_id = 0) const uint TILE = 16u;  // the tile's side in pixels, a multiple of the workgroup's

layout(std430, set = 0, binding = 0) readonly buffer Visibility { uint64_t visibility[]; };
layout(std430, set = 0, binding = 1) buffer Tiles {
    VisibilityTileList list;
    uint tiles[];
};
layout(push_constant) uniform Push { uvec4 extent; };  // xy: the visibility buffer's extent in pixels

shared uint covered;

void main() {
    if (gl_LocalInvocationIndex == 0u) covered = 0u;
    barrier();
    const uvec2 origin = gl_WorkGroupID.xy * TILE;
    bool drawn = false;
    for (uint y = gl_LocalInvocationID.y; y < TILE && !drawn; y += VISIBILITY_TILE_GROUP) {
        for (uint x = gl_LocalInvocationID.x; x < TILE && !drawn; x += VISIBILITY_TILE_GROUP) {
            const uvec2 pixel = origin + uvec2(x, y);
            if (all(lessThan(pixel, extent.xy)))
                drawn = uint(visibility[pixel.y * extent.x + pixel.x] >> 32) != VISIBILITY_EMPTY_HIGH;
        }
    }
    if (drawn) atomicOr(covered, 1u);
    barrier();
    if (gl_LocalInvocationIndex == 0u && covered != 0u)
        tiles[atomicAdd(list.instanceCount, 1u)] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16);
}
