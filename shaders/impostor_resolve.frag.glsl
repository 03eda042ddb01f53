#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The visibility buffer's resolve, inside the colour pass after the hardware-drawn meshes and
// impostors: a pixel the compute rasterizer covered decodes its impostor from the id, finds the same
// point of the same quad (impostor_raster_pixel.glsl.inc), shades it as impostor.frag.glsl does
// (impostor_shade.glsl.inc) and writes the rasterizer's depth as gl_FragDepth, so the depth test
// merges it with the hardware-drawn characters exactly as a hardware-drawn impostor would be.
#include "gpu_types.h"
#include "shading.glsl.inc"
#include "impostor_set.glsl.inc"
#include "impostor_prop_set.glsl.inc"
#include "impostor_pose.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_quad.glsl.inc"
#include "impostor_raster_pixel.glsl.inc"
#include "impostor_sample.glsl.inc"
#include "impostor_normal.glsl.inc"
#include "impostor_shade.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(set = 2, binding = 0) uniform sampler2DArray atlasAlbedo;
layout(set = 2, binding = 1) uniform sampler2DArray atlasNormal;
layout(std430, set = 3, binding = 0) readonly buffer Visibility { uint64_t visibility[]; };
layout(push_constant) uniform Push {
    vec4 cameraPosition;  // xyz: the eye; w: 1 to blend the atlas cells, 0 the nearest (impostor-blend)
    vec4 viewport;  // xy: offset in the target, zw: extent (the visibility buffer's)
};
layout(location = 0) out vec4 outColor;

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy - viewport.xy);
    uint64_t word = visibility[pixel.y * uint(viewport.z) + pixel.x];
    uint depthBits = uint(word >> 32);
    if (depthBits == VISIBILITY_EMPTY_HIGH) discard;
    CharacterRecord character = characters[impostors[uint(word & 0xFFFFFFFFul)]];
    ImpostorQuad q = impostorQuad(character, impostorModelOf(character), cameraPosition.xyz, false, vec3(0.0));
    const bool blend = cameraPosition.w != 0.0;
    if (!blend) q.blend = impostorNearest(q.blend);
    ImpostorPixel p = impostorPixel(impostorQuadClip(q, scene.viewProjection), vec2(pixel), viewport.zw);
    impostorUseGradients(p, q.grid);
    vec4 albedo = impostorTexel(atlasAlbedo, blend, q.blend, q.grid, p.local);
    outColor = vec4(impostorShade(scene, atlasNormal, blend, q.blend, q.grid, p.local, albedo,
                                  character.tint.rgb, q.heading, impostorCorner(q, p.corner), q.halfSide,
                                  cameraPosition.xyz), 1.0);
    gl_FragDepth = uintBitsToFloat(depthBits);
}
