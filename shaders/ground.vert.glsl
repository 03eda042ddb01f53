#version 460
#extension GL_GOOGLE_include_directive : require
// A ground quad at y = 0 under the crowd, generated from gl_VertexIndex (no vertex buffer).
#include "gpu_types.h"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
// x, z: centre; w: half extent in metres.
layout(push_constant) uniform Push { vec4 cameraPosition; vec4 area; };
layout(location = 0) out vec3 outWorld;

void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(-1, 1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(1, -1));
    vec2 c = corners[gl_VertexIndex];
    vec3 world = vec3(area.x + c.x * area.w, 0.0, area.z + c.y * area.w);
    gl_Position = scene.viewProjection * vec4(world, 1.0);
    outWorld = world;
}
