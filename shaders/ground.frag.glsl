#version 460
#extension GL_GOOGLE_include_directive : require
// A checkered ground: the tiles give a sense of scale and of distance.
#include "gpu_types.h"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; vec4 area; };
layout(location = 0) in vec3 inWorld;
layout(location = 0) out vec4 outColor;

void main() {
    vec2 tile = floor(inWorld.xz / scene.groundColor.w);
    float checker = mod(tile.x + tile.y, 2.0) == 0.0 ? 1.0 : 0.86;
    vec3 albedo = scene.groundColor.rgb * checker;
    outColor = vec4(shade(scene, vec3(0.0, 1.0, 0.0), albedo, inWorld, cameraPosition.xyz), 1.0);
}
