#version 460
// Each texel's depth as the compute rasterizer left it (shaders/shadow_raster.comp.glsl): its bits.
layout(std430, set = 0, binding = 0) readonly buffer Depth { uint depth[]; };
layout(push_constant) uniform Push { uint size; } push;

void main() {
    const uvec2 texel = uvec2(gl_FragCoord.xy);
    gl_FragDepth = uintBitsToFloat(depth[texel.y * push.size + texel.x]);
}
