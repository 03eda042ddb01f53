#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The mesh visibility buffer's resolve, inside the colour pass (docs/compute-raster.md, "Meshes"): a
// pixel the compute rasterizer covered decodes its character and triangle from the id, reads the
// triangle's three skinned vertices, interpolates at the pixel centre what the draw pass's vertex
// shader hands its fragment shader (perspective-correct, as the hardware interpolates), shades it with
// the same shade(), and writes the rasterizer's depth as gl_FragDepth, so the depth test merges it
// with the hardware-drawn characters and the impostors.
#include "gpu_types.h"
#include "shading.glsl.inc"

// A texture read needs its footprint: with no 2x2 pixel quad to difference, the gradients are those of
// the uv at the next pixel centres right and down on the same triangle's plane.
vec2 gUvDx, gUvDy;
#define BASE_COLOR_FETCH(image, uv) textureGrad(image, uv, gUvDx, gUvDy)
#include "base_color.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(std430, set = 1, binding = 0) readonly buffer Draws { DrawIndexedCommand draws[]; };
layout(std430, set = 1, binding = 1) readonly buffer Listed { uint listed[]; };
layout(std430, set = 1, binding = 2) readonly buffer Indices { uint indices[]; };
layout(std430, set = 1, binding = 3) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 1, binding = 4) readonly buffer Normals { vec4 normals[]; };  // xyz + pooled material
layout(std430, set = 1, binding = 5) readonly buffer Models { ModelRecord models[]; };
layout(std430, set = 1, binding = 6) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 1, binding = 7) readonly buffer Visibility { uint64_t visibility[]; };
// The pooled texture coordinates (the scene set's binding 2 is the vertex stage's alone).
layout(std430, set = 1, binding = 8) readonly buffer MeshUvs { vec2 meshUvs[]; };
layout(push_constant) uniform Push {
    vec4 cameraPosition;  // xyz: the eye
    vec4 viewport;        // xy: offset in the target, zw: extent (the visibility buffer's)
    uvec4 idLayout;       // x: triangle bits of an id
};
layout(location = 0) out vec4 outColor;

// Perspective-correct barycentric weights of the triangle (clip-space corners) at a pixel centre.
vec3 weightsAt(vec4 c0, vec4 c1, vec4 c2, vec2 centre) {
    const vec2 s0 = (c0.xy / c0.w * 0.5 + 0.5) * viewport.zw, s1 = (c1.xy / c1.w * 0.5 + 0.5) * viewport.zw,
               s2 = (c2.xy / c2.w * 0.5 + 0.5) * viewport.zw;
    // Screen-space weights from the edge functions, then each divided by its corner's w.
    const float l0 = (s2.x - s1.x) * (centre.y - s1.y) - (s2.y - s1.y) * (centre.x - s1.x);
    const float l1 = (s0.x - s2.x) * (centre.y - s2.y) - (s0.y - s2.y) * (centre.x - s2.x);
    const float l2 = (s1.x - s0.x) * (centre.y - s0.y) - (s1.y - s0.y) * (centre.x - s0.x);
    const vec3 perspective = vec3(l0 / c0.w, l1 / c1.w, l2 / c2.w);
    return perspective / (perspective.x + perspective.y + perspective.z);
}

void main() {
    const uvec2 pixel = uvec2(gl_FragCoord.xy - viewport.xy);
    const uint64_t word = visibility[pixel.y * uint(viewport.z) + pixel.x];
    const uint depthBits = uint(word >> 32);
    if (depthBits == VISIBILITY_EMPTY_HIGH) discard;
    const uint id = uint(word & 0xFFFFFFFFul) & ~MESH_RASTER_ID_BIT;
    const DrawIndexedCommand command = draws[listed[id >> idLayout.x]];
    const uint first = command.firstIndex + 3u * (id & ((1u << idLayout.x) - 1u));
    const uvec3 local = uvec3(indices[first], indices[first + 1u], indices[first + 2u]);  // the model's own
    const uvec3 vertex = uvec3(ivec3(local) + command.vertexOffset);
    const vec3 w0 = positions[vertex.x].xyz, w1 = positions[vertex.y].xyz, w2 = positions[vertex.z].xyz;
    const vec4 c0 = scene.viewProjection * vec4(w0, 1.0), c1 = scene.viewProjection * vec4(w1, 1.0),
               c2 = scene.viewProjection * vec4(w2, 1.0);
    const vec2 centre = vec2(pixel) + 0.5;
    const vec3 b = weightsAt(c0, c1, c2, centre);

    const CharacterRecord character = characters[command.firstInstance];
    const ModelRecord model = models[character.ids.x];
    const vec4 n0 = normals[vertex.x], n1 = normals[vertex.y], n2 = normals[vertex.z];
    const vec3 normal = b.x * n0.xyz + b.y * n1.xyz + b.z * n2.xyz;
    const vec3 albedo = b.x * characterColor(uint(n0.w), character.tint.rgb) +
                        b.y * characterColor(uint(n1.w), character.tint.rgb) +
                        b.z * characterColor(uint(n2.w), character.tint.rgb);
    const vec2 u0 = meshUvs[model.info.x + local.x], u1 = meshUvs[model.info.x + local.y],
               u2 = meshUvs[model.info.x + local.z];
    const vec3 bx = weightsAt(c0, c1, c2, centre + vec2(1.0, 0.0)), by = weightsAt(c0, c1, c2, centre + vec2(0.0, 1.0));
    const vec2 uv = b.x * u0 + b.y * u1 + b.z * u2;
    gUvDx = bx.x * u0 + bx.y * u1 + bx.z * u2 - uv;
    gUvDy = by.x * u0 + by.y * u1 + by.z * u2 - uv;
    // The provoking (first) vertex's slot, as the draw pass's flat varying.
    const uint slot = textureSlot(uint(n0.w), model);
    const vec3 world = b.x * w0 + b.y * w1 + b.z * w2;
    outColor = vec4(shade(scene, normal, albedo * sampleBaseColor(slot, uv), world, cameraPosition.xyz), 1.0);
    gl_FragDepth = uintBitsToFloat(depthBits);
}
