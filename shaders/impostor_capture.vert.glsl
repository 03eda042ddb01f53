#version 460
#extension GL_GOOGLE_include_directive : require
// The impostor bake: one model in one pose seen from one view, into one atlas cell. The pose's bones
// come from the CPU animation jobs; skinning is the engine's (skinning.glsl.inc), the projection an
// orthographic one onto the view's image plane (impostorBasis) over the square that holds the pose sphere.
#include "gpu_types.h"
#include "skinning.glsl.inc"
#include "shading.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(std430, set = 1, binding = 0) readonly buffer Models { ModelRecord models[]; };
layout(std430, set = 1, binding = 1) readonly buffer Bones { BoneRows bones[]; };

layout(push_constant) uniform Push {
    vec4 square;         // model space: xyz centre, w half side
    vec4 right;          // xyz: the image plane's right
    vec4 up;             // xyz: its up
    vec4 towardsCamera;  // xyz: the view direction, pointing at the viewer
    uvec4 pose;          // x: first bone of the pose, y: model
};

layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;
layout(location = 2) in uvec4 inJoints;
layout(location = 3) in vec4 inWeights;

layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vAlbedo;
layout(location = 2) out vec2 vUv;
layout(location = 3) flat out uint vTextureSlot;

void main() {
    uint base = pose.x;
    SkinVertex v = SkinVertex(inPosition, inNormal, inJoints, inWeights);
    Skinned s = skinVertex(v, bones[base + inJoints.x], bones[base + inJoints.y], bones[base + inJoints.z],
                           bones[base + inJoints.w]);
    vec3 p = s.position - square.xyz;
    // Vulkan's clip y points down the image, so up is -y; depth 0 nearest the viewer, 1 farthest.
    gl_Position = vec4(dot(p, right.xyz) / square.w, -dot(p, up.xyz) / square.w,
                       0.5 - 0.5 * dot(p, towardsCamera.xyz) / square.w, 1.0);
    uint material = uint(inNormal.w);
    vNormal = s.normal;
    // Untinted: the impostor multiplies by each character's tint, as the mesh draw does.
    vAlbedo = characterColor(material, vec3(1.0));
    vUv = textureCoordinates[uint(gl_VertexIndex)];
    vTextureSlot = textureSlot(material, models[pose.y]);
}
