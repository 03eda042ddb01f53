#version 460
// The sky: one triangle over the viewport at the far plane (depth 1), so that, tested less-or-equal
// against the cleared depth and drawn after everything opaque, it colours only the pixels nothing
// else drew. No vertex buffer.
void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);  // (0,0), (2,0), (0,2)
    gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
}
