#version 460
// One triangle over the whole shadow map (render/shadow_raster.h): the compute-rasterized depth is
// written into the map's depth image, where the impostor casters are then drawn over it.
void main() {
    const vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
