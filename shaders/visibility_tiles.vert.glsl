#version 460
// The visibility buffer's resolve over the covered tiles (render/visibility_resolve.h): an instance per
// tile the scan listed, two triangles over its pixels (trimmed to the viewport); the fragment shader
// (impostor_resolve or mesh_resolve) decodes each pixel and writes its depth.
layout(constant_id = 0) const uint TILE = 16u;  // the tile's side in pixels, as the scan's

layout(location = 0) in uint tile;  // x | y << 16, in tiles
// Both resolves' push constants hold the viewport at byte 16: xy its offset in the target, zw its extent.
layout(push_constant) uniform Push { layout(offset = 16) vec4 viewport; };

void main() {
    // Vertices 0..5: corners (0,0) (1,0) (0,1) and (0,1) (1,0) (1,1), x and y as bits of two masks.
    const uint i = uint(gl_VertexIndex);
    const uvec2 corner = uvec2((0x32u >> i) & 1u, (0x2Cu >> i) & 1u);
    const uvec2 pixel = min((uvec2(tile & 0xFFFFu, tile >> 16) + corner) * TILE, uvec2(viewport.zw));
    gl_Position = vec4(vec2(pixel) / viewport.zw * 2.0 - 1.0, 0.0, 1.0);
}
