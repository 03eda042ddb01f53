#version 460
// Pass 1 geometry: one triangle that covers the whole skinning target, so every texel
// (one per character and vertex) runs the fragment shader exactly once.
void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
