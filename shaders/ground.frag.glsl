#version 460
#extension GL_GOOGLE_include_directive : require
// A checkered ground: the tiles give a sense of scale and of distance.
#include "gpu_types.h"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; vec4 area; };
layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec4 outColor;
// Off only in tests, which measure what the filter gains against the tiles point-sampled.
layout(constant_id = 0) const bool kFilteredTiles = true;
// Off only in tests: the sunlight from the shadow map's comparisons at each pixel, the reference.
layout(constant_id = 1) const bool kSunlightImage = true;
// The shadow map's comparisons on the ground, per map texel, mipmapped (render/ground_sunlight.h).
layout(set = 0, binding = 4) uniform sampler2D groundSunlight;
TERRAIN_BUFFER(0, 6);
#include "terrain_height.h"

// The share of the pixel's footprint that lies on odd tiles (tile.x + tile.y odd), for `p` in tile
// units: the checker's square wave box-filtered over the footprint, which is the difference of its
// integral (a triangle wave) across the footprint's width (Inigo Quilez, "filtered checkerboard").
// Point-sampling the tiles, as before, aliases into moiré once a tile is under a pixel; integrated,
// the far ground converges to the tiles' average colour. The footprint is the screen-space
// derivatives' box (fwidth per axis), so it widens along the view at grazing angles, as it must.
float oddTileShare(vec2 p) {
    vec2 w = kFilteredTiles ? abs(dFdx(p)) + abs(dFdy(p)) + 1e-4 : vec2(1e-4);  // + a little: no 0 / 0
    vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
    return 0.5 - 0.5 * i.x * i.y;  // i: +1 on even, -1 on odd columns (rows), averaged over the box
}

// The sunlight on the ground here: one trilinear fetch of the ground sunlight image, whose texels are
// the comparisons sunlight() would make at their centres and whose levels average them, so the far
// ground's shadows are filtered over the pixel's footprint too. Outside the map: lit, as sunlight().
// The level comes from the ground's footprint in the cascade it falls in (the uv jumps where two
// cascades meet, so the hardware's derivatives of it would pick a coarse level along the seam), and
// the fetch stays inside that cascade's square, whose coarse texels would otherwise mix in its neighbour's.
float groundSunlightAt(vec3 world) {
    vec3 dx = dFdx(world), dy = dFdy(world);  // before any branch: derivatives need the whole quad
    // The image holds the plane y = 0's sunlight: over a terrain, the map's comparisons at the pixel.
    if (!kSunlightImage || terrainOn(terrainGrid)) return sunlight(scene, world);
    if (scene.shadow.x == 0.0) return 1.0;
    if (scene.shadowCascadeUse.x == 1.0) {  // one map over the view, as before cascades (its cost too)
        vec2 uv = (scene.shadowLight * vec4(world, 1.0)).xy * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
        float lod = clamp(textureQueryLod(groundSunlight, uv).y, scene.shadow.w, scene.shadow.w + 4.0);
        return textureLod(groundSunlight, uv, lod).r;
    }
    ShadowLookup l = shadowLookup(scene, world, dx, dy);
    if (l.cascade < 0) return 1.0;
    float texels = float(textureSize(groundSunlight, 0).x);
    float footprint = max(length(l.uvDx), length(l.uvDy)) * texels;
    // Within the five levels made this frame, from the first (finer ones are a small viewport's leftovers,
    // coarser ones never made).
    float lod = clamp(log2(max(footprint, 1e-8)), scene.shadow.w, scene.shadow.w + 4.0);
    float inset = 0.5 * exp2(ceil(lod)) / texels;
    vec2 uv = clamp(l.uv, l.square.xy + inset, l.square.xy + l.square.z - inset);
    return textureLod(groundSunlight, uv, lod).r;
}

void main() {
    float checker = mix(1.0, 0.86, oddTileShare(inWorld.xz / scene.groundColor.w));
    vec3 albedo = scene.groundColor.rgb * checker;
    vec3 color = shadeWithSunlight(scene, normalize(inNormal), albedo, inWorld, groundSunlightAt(inWorld), cameraPosition.xyz);
    outColor = vec4(color, 1.0);
}
