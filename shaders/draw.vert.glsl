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
// The colour pass's undithered pipeline: a fading character is drawn by the dithering one from its own
// list (cull_emit.comp.glsl), so here its triangles collapse to a point outside the view.
layout(constant_id = 0) const bool kSkipFading = false;
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inNormal;

void main() {
    if (kSkipFading && (characterStates[gl_InstanceIndex] >> FADE_SHIFT) != 0u) {
        gl_Position = vec4(0.0, 0.0, -1.0, 1.0);  // in front of the near plane: clipped
        return;
    }
    CharacterRecord character = characters[gl_InstanceIndex];
    ModelRecord model = models[character.ids.x];
    uint material = uint(inNormal.w);
    gl_Position = scene.viewProjection * vec4(inPosition.xyz, 1.0);
    vNormal = inNormal.xyz;
    vAlbedo = characterColor(scene, material, character.tint.rgb);
    // Minus the draw's vertexOffset, the vertex index is the model's own.
    vUv = textureCoordinates[model.info.x + uint(gl_VertexIndex - gl_BaseVertexARB)];
    vTextureSlot = textureSlot(scene, material, model);
    vWorld = inPosition.xyz;
    vFadeShare = fadeShareOf(characterStates[gl_InstanceIndex]);
}
