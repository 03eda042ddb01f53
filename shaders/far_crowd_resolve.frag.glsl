#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The far layer's resolve (docs/picture-quality.md, "The far crowd averaged"), last in the colour pass:
// a pixel the far impostors covered takes their coverage-weighted means (far_crowd.glsl.inc: albedo,
// normal, pose-sphere radius), lights them once as an impostor pixel is lit (impostorShadeSurface) at
// the point of the nearest contribution, and is blended over what is behind by its coverage. Its
// depth is that nearest contribution's, tested but not written: a nearer mesh or opaque impostor
// hides the layer, and the layer hides nothing (it is a part of a pixel, not the whole).
#include "gpu_types.h"
#include "shading.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_sample.glsl.inc"
#include "impostor_normal.glsl.inc"
#include "impostor_shade.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(std430, set = 1, binding = 0) readonly buffer FarDepth { uint64_t farDepth[]; };
layout(std430, set = 1, binding = 1) readonly buffer FarSums { uint farSums[]; };
layout(push_constant) uniform Push {
    vec4 cameraPosition;  // xyz: the eye
    vec4 viewport;  // xy: offset in the target, zw: extent (the far layer's)
};
layout(location = 0) out vec4 outColor;

float farSum(uint base, uint channel) { return float(farSums[base + channel]) / FAR_CROWD_ONE; }

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy - viewport.xy);
    uint at = pixel.y * uint(viewport.z) + pixel.x;
    uint depthBits = uint(farDepth[at] >> 32);
    if (depthBits == VISIBILITY_EMPTY_HIGH) discard;
    uint base = at * uint(FAR_CROWD_CHANNELS);
    float opticalDepth = farSum(base, 3u);  // the weights' sum (far_crowd.glsl.inc, farOpticalDepth)
    if (opticalDepth <= 0.0) discard;
    vec3 albedo = vec3(farSum(base, 0u), farSum(base, 1u), farSum(base, 2u)) / opticalDepth;
    vec3 normal = vec3(farSum(base, 4u), farSum(base, 5u), farSum(base, 6u)) / opticalDepth * 2.0 - 1.0;
    float radius = farSum(base, 7u) / opticalDepth;
    float depth = uintBitsToFloat(depthBits);
    // The nearest contribution's point: the pixel centre at that depth, back through the view-projection.
    vec2 ndc = (vec2(pixel) + 0.5) / viewport.zw * 2.0 - 1.0;
    vec4 world = inverse(scene.viewProjection) * vec4(ndc, depth, 1.0);
    vec3 colour = impostorShadeSurface(scene, normal, albedo, world.xyz / world.w, radius, cameraPosition.xyz);
    // Independent layers leave exp(-sum) of the pixel uncovered.
    outColor = vec4(colour, 1.0 - exp(-opticalDepth));
    gl_FragDepth = depth;
}
