#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_draw_parameters : require
// The draw pass from already-skinned world-space vertices (position; normal + pooled material).
// Each draw is one character: firstInstance is its index, vertexOffset its first skinned vertex.
#include "gpu_types.h"
#include "shading.glsl.inc"
#include "crowd_set.glsl.inc"
#include "fade_dither.glsl.inc"
#define VARYING out
#include "draw_varyings.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;

void main() {
    CharacterRecord character = characters[gl_InstanceIndex];
    ModelRecord model = models[character.ids.x];
    uint material = uint(inNormal.w);
    gl_Position = scene.viewProjection * vec4(inPosition.xyz, 1.0);
    vNormal = inNormal.xyz;
    // Minus the draw's vertexOffset, the vertex index is the model's own.
    vUv = textureCoordinates[model.info.x + uint(gl_VertexIndex - gl_BaseVertexARB)];
    vWorld = inPosition.xyz;
    vMaterial = drawMaterial(characterColor(material, character.tint.rgb), textureSlot(material, model),
                             characterStates[gl_InstanceIndex] >> FADE_SHIFT);
}
