#version 460
#extension GL_GOOGLE_include_directive : require
// The ground under the crowd, generated from gl_VertexIndex (no vertex buffer): without terrain a quad at
// y = 0; with the host's heightfield its grid (render/terrain_buffer.h), every stride-th sample line,
// with a ring of cells out to the ground's edge where the edge's heights go on.
#include "gpu_types.h"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
TERRAIN_BUFFER(0, 6);
// x, z: centre; w: half extent in metres.
layout(push_constant) uniform Push { vec4 cameraPosition; vec4 area; };
layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;

#include "terrain_sample.glsl.inc"

const uvec2 kCorners[6] = uvec2[](uvec2(0, 0), uvec2(0, 1), uvec2(1, 1), uvec2(0, 0), uvec2(1, 1), uvec2(1, 0));

uint groundStride(uint samples) { return max(1u, (samples - 2u) / GROUND_MOST_CELLS + 1u); }

// Where line `i` of the ground lies along one axis: the ground's edge, the grid's lines, the far edge.
float lineAt(uint i, uint inner, uint stride, uint samples, float first, float width, float areaLo, float areaHi) {
    if (i == 0u) return min(areaLo, first);
    if (i == inner + 2u) return max(areaHi, first + width);
    return first + width * float(min((i - 1u) * stride, samples - 1u)) / float(samples - 1u);
}

void main() {
    if (!terrainOn(terrainGrid)) {
        vec2 c = vec2(kCorners[gl_VertexIndex]) * 2.0 - 1.0;
        vec3 world = vec3(area.x + c.x * area.w, 0.0, area.z + c.y * area.w);
        gl_Position = scene.viewProjection * vec4(world, 1.0);
        outWorld = world;
        outNormal = vec3(0.0, 1.0, 0.0);
        return;
    }
    TerrainGrid grid = terrainGrid;
    uvec2 stride = uvec2(groundStride(grid.size.x), groundStride(grid.size.y));
    uvec2 inner = (grid.size.xy - 1u + stride - 1u) / stride;  // the grid's cells along each axis
    uint across = inner.x + 2u;
    uint cell = uint(gl_VertexIndex) / 6u;
    uvec2 line = uvec2(cell % across, cell / across) + kCorners[uint(gl_VertexIndex) % 6u];
    vec2 ground = vec2(lineAt(line.x, inner.x, stride.x, grid.size.x, grid.extent.x, grid.extent.z, area.x - area.w, area.x + area.w),
                       lineAt(line.y, inner.y, stride.y, grid.size.y, grid.extent.y, grid.extent.w, area.z - area.w, area.z + area.w));
    vec3 world = vec3(ground.x, terrainHeightAt(grid, ground), ground.y);
    // The normal from the heights a sample's spacing either side (flat beyond the grid, where they go on).
    vec2 step = grid.extent.zw / vec2(grid.size.xy - 1u) * vec2(stride);
    float dx = terrainHeightAt(grid, ground + vec2(step.x, 0.0)) - terrainHeightAt(grid, ground - vec2(step.x, 0.0));
    float dz = terrainHeightAt(grid, ground + vec2(0.0, step.y)) - terrainHeightAt(grid, ground - vec2(0.0, step.y));
    outNormal = normalize(vec3(-dx / (2.0 * step.x), 1.0, -dz / (2.0 * step.y)));
    gl_Position = scene.viewProjection * vec4(world, 1.0);
    outWorld = world;
}
