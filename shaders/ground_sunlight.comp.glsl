#version 460
#extension GL_GOOGLE_include_directive : require
// The ground's sunlight, once per shadow-map texel instead of once per screen pixel (issue 18, "shadows
// that cost what they show"). The ground is the plane y = 0 and the light's projection is orthographic,
// so each texel centre of the map sees exactly one ground point: its filtered comparison is computed
// here, in compute, and the ground's fragment shader takes one trilinear fetch of the result where it
// made its comparisons (on the H100 fragment work runs on a small graphics slice; this pass runs on
// every SM). Each workgroup computes a 16x16 block of the first level and, in shared memory, its means
// down to one texel four levels below, so the far ground, where a texel is smaller than a pixel,
// averages its shadows instead of aliasing, in one dispatch (no barrier between levels). The first level
// is 0 unless the viewport is too small to show the map's texels (render/ground_sunlight.h). With shadow
// cascades, one dispatch a cascade covers its square of the map (render/shadow_cascades.h).
layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform sampler2DShadow shadowMap;
// The first level made and the four below it.
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D level0;
layout(set = 0, binding = 2, rgba8) uniform writeonly image2D level1;
layout(set = 0, binding = 3, rgba8) uniform writeonly image2D level2;
layout(set = 0, binding = 4, rgba8) uniform writeonly image2D level3;
layout(set = 0, binding = 5, rgba8) uniform writeonly image2D level4;
layout(push_constant) uniform Push {
    mat4 lightViewProjection;  // the cascade's: world to its clip space
    vec4 shadow;  // y: depth bias, z: one texel of the map in uv (as SceneUniforms::shadow)
    uint size;    // the first level's side in texels
    uint levels;  // levels to write (1 to 5: fewer for maps under 16 texels)
    float step;   // map texels per texel of the first level (a power of two)
    uint side;    // the cascade's square's side in texels of the first level (a multiple of 16, or `size`)
    uvec2 origin; // its corner, in texels of the first level
} push;

#include "shadow_pcf.glsl.inc"

shared float block[16 * 16];

// The sunlight at the ground point under the first level's texel `texel` (as sunlight() in
// shading.glsl.inc computes it for that point: beyond the map's depth range, lit), its filter widened to
// the texel's footprint in the map and kept inside the cascade's square (its outermost texels, which
// the shading never takes, would read the neighbouring cascade's).
float groundSunlightAt(uvec2 texel) {
    const vec2 local = (vec2(texel - push.origin) + 0.5) / float(push.side);
    const mat4 m = push.lightViewProjection;
    // clip.xy = m[0].xy * x + m[2].xy * z + m[3].xy on the plane y = 0: solve for (x, z).
    const vec2 xz = inverse(mat2(m[0].xy, m[2].xy)) * (local * 2.0 - 1.0 - m[3].xy);
    const float depth = m[0].z * xz.x + m[2].z * xz.y + m[3].z;
    if (depth > 1.0) return 1.0;
    const float reach = push.shadow.z * push.step;  // the filter's, in uv
    const vec2 lo = vec2(push.origin) / float(push.size) + reach, hi = vec2(push.origin + push.side) / float(push.size) - reach;
    const vec2 uv = clamp((vec2(texel) + 0.5) / float(push.size), lo, hi);
    return shadowMapSunlight(shadowMap, uv, depth - push.shadow.y, reach);
}

// Level k's texel of this thread (k >= 1, the threads of the block's first 16 >> k rows and columns):
// the mean of the 2x2 level k - 1 texels the block holds, which then take its place in the block.
float halve(uint k) {
    const uvec2 local = gl_LocalInvocationID.xy;
    const bool mine = all(lessThan(local, uvec2(16u >> k)));
    float mean = 0.0;
    if (mine) {
        const uint i = local.y * 32u + local.x * 2u;
        mean = 0.25 * (block[i] + block[i + 1u] + block[i + 16u] + block[i + 17u]);
    }
    barrier();
    if (mine) block[local.y * 16u + local.x] = mean;
    barrier();
    return mean;
}

// Stores level k's texel of this thread where that level has it.
bool ownsTexel(uint k, out ivec2 texel) {
    const uvec2 inSquare = (gl_WorkGroupID.xy * 16u >> k) + gl_LocalInvocationID.xy;
    texel = ivec2((push.origin >> k) + inSquare);
    return k < push.levels && all(lessThan(gl_LocalInvocationID.xy, uvec2(16u >> k))) &&
           all(lessThan(inSquare, uvec2(max(push.side >> k, 1u))));
}

void main() {
    // Threads past the square's edge take its last texel, so the means near the edge stay defined.
    const uvec2 texel0 = push.origin + min(gl_GlobalInvocationID.xy, uvec2(push.side - 1u));
    const float lit = groundSunlightAt(texel0);
    ivec2 texel;
    if (ownsTexel(0u, texel)) imageStore(level0, texel, vec4(lit));
    block[gl_LocalInvocationID.y * 16u + gl_LocalInvocationID.x] = lit;
    barrier();
    float mean = halve(1u);
    if (ownsTexel(1u, texel)) imageStore(level1, texel, vec4(mean));
    mean = halve(2u);
    if (ownsTexel(2u, texel)) imageStore(level2, texel, vec4(mean));
    mean = halve(3u);
    if (ownsTexel(3u, texel)) imageStore(level3, texel, vec4(mean));
    mean = halve(4u);
    if (ownsTexel(4u, texel)) imageStore(level4, texel, vec4(mean));
}
