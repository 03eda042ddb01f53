// The ground's height from the host's heightfield (crowd/terrain.h, docs/host-driven.md), written once
// for C++ and GLSL like shaders/driven_keys.h: C++ includes it inside a namespace with glm's functions and
// gpu_types.h's types (crowd/terrain.cpp); GLSL after gpu_types.h. Each side fetches the cell's four
// heights from where it keeps them.
#ifndef CROWD_TERRAIN_HEIGHT_H
#define CROWD_TERRAIN_HEIGHT_H

#ifdef __cplusplus
#define TERRAIN_FN inline
#else
#define TERRAIN_FN
#endif

// The grid cell under a ground point and where in it: the index of its first corner's height (row-major:
// column + row x columns; the others are +1, +columns, +columns+1) and the fractions across it (x, z).
// Beyond the grid the edge's heights go on (clamped).
struct TerrainCell {
    uint first;
    vec2 fraction;
};

TERRAIN_FN TerrainCell terrainCellOf(TerrainGrid grid, vec2 p) {
    vec2 cells = vec2(float(grid.size.x - 1u), float(grid.size.y - 1u));
    vec2 at = clamp((p - vec2(grid.extent.x, grid.extent.y)) / vec2(grid.extent.z, grid.extent.w), vec2(0.0f),
                    vec2(1.0f)) * cells;
    uint column = min(uint(at.x), grid.size.x - 2u), row = min(uint(at.y), grid.size.y - 2u);
    TerrainCell cell;
    cell.first = column + row * grid.size.x;
    cell.fraction = at - vec2(float(column), float(row));
    return cell;
}

// The height inside a cell from its corners' (bilinear).
TERRAIN_FN float terrainBlend(float h00, float h10, float h01, float h11, vec2 f) {
    return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

// Whether there is terrain at all (a flat ground at y = 0 has none).
TERRAIN_FN bool terrainOn(TerrainGrid grid) { return grid.extent.z > 0.0f; }

#endif
