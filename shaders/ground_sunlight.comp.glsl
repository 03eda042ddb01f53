#version 460
#extension GL_GOOGLE_include_directive : require
// The ground's sunlight, once per shadow-map texel instead of once per screen pixel (issue 18, "shadows
// that cost what they show"). The ground is the plane y = 0 and the light's projection is orthographic,
// so each texel centre of the map sees exactly one ground point: its filtered comparison is computed
// here, in compute, and the ground's fragment shader takes one trilinear fetch of the result where it
// made its comparisons (on the H100 fragment work runs on a small graphics slice; this pass runs on
// every SM). Level 0 holds the comparisons; each higher level the mean of 2x2 texels of the one below,
// so the far ground, where a texel is smaller than a pixel, averages its shadows instead of aliasing.
layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const bool kFirstLevel = true;

layout(set = 0, binding = 0) uniform sampler2DShadow shadowMap;
layout(set = 0, binding = 1, rgba8) uniform readonly image2D below;  // the level below (not read by level 0)
layout(set = 0, binding = 2, rgba8) uniform writeonly image2D level;
layout(push_constant) uniform Push {
    mat4 lightViewProjection;
    vec4 shadow;  // y: depth bias, z: one texel of the map in uv (as SceneUniforms::shadow)
} push;

#include "shadow_pcf.glsl.inc"

// The sunlight at the ground point under the map's texel `texel` (as sunlight() in shading.glsl.inc
// computes it for that point: beyond the map's depth range, lit).
float groundSunlightAt(ivec2 texel, ivec2 size) {
    const vec2 uv = (vec2(texel) + 0.5) / vec2(size);
    const mat4 m = push.lightViewProjection;
    // clip.xy = m[0].xy * x + m[2].xy * z + m[3].xy on the plane y = 0: solve for (x, z).
    const vec2 xz = inverse(mat2(m[0].xy, m[2].xy)) * (uv * 2.0 - 1.0 - m[3].xy);
    const float depth = m[0].z * xz.x + m[2].z * xz.y + m[3].z;
    if (depth > 1.0) return 1.0;
    return shadowMapSunlight(shadowMap, uv, depth - push.shadow.y, push.shadow.z);
}

void main() {
    const ivec2 size = imageSize(level);
    const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, size))) return;
    float lit;
    if (kFirstLevel) {
        lit = groundSunlightAt(texel, size);
    } else {
        const ivec2 source = min(texel * 2, imageSize(below) - 2);  // levels of odd size: clamp
        lit = 0.25 * (imageLoad(below, source).r + imageLoad(below, source + ivec2(1, 0)).r +
                      imageLoad(below, source + ivec2(0, 1)).r + imageLoad(below, source + ivec2(1, 1)).r);
    }
    imageStore(level, texel, vec4(lit));
}
