#version 460
#extension GL_GOOGLE_include_directive : require
// The impostor level: four vertices per character of the impostor list (vertex v is corner v % 4 of
// impostor v / 4; indexed quads share them, and the draw's cost follows the vertices), a quad facing
// the eye (spherical billboard over the model's pose sphere, turned by the character's heading) that
// shows the atlas cells of its clip, phase and view direction, blended (impostorBlend: the fragment
// shader mixes the cells, so it gets the lower band's four cells, the step to the upper band's, the
// three weights and the place in a cell). No bones, no skinned vertices: only the
// record. The shadow pass draws the same quads facing the light (SHADOW_PASS, with the light's scene set):
// for an orthographic light, the atlas cell seen from the light's direction is the character's
// silhouette as the light sees it, at the pose the colour pass shows; in the nearest elevation band
// only (impostorNearestBand: the light is fixed, so its band does not change).
#include "gpu_types.h"
#include "impostor_set.glsl.inc"
#include "impostor_prop_set.glsl.inc"
#include "impostor_pose.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "fade_dither.glsl.inc"
#include "impostor_quad.glsl.inc"

layout(set = 0, binding = 0) uniform Scene { SceneUniforms scene; };
layout(push_constant) uniform Push { vec4 cameraPosition; };
layout(constant_id = 0) const bool SHADOW_PASS = false;
layout(constant_id = 1) const bool BLEND = true;  // impostor-blend: four cells, or the nearest one

layout(location = 0) out vec2 vLocal;        // the place in a cell, [0, 1]^2 over the quad
layout(location = 1) flat out uvec4 vCells;   // impostorBlend's four cells of the lower band
layout(location = 2) flat out vec3 vTint;
layout(location = 3) flat out vec2 vHeading;  // cos, sin
layout(location = 4) out vec3 vWorld;
layout(location = 5) flat out float vRadius;
layout(location = 6) flat out vec3 vWeights;  // impostorBlend's weights (azimuth, frame, band)
layout(location = 7) flat out uvec2 vGrid;    // cells per atlas row, per layer
layout(location = 8) flat out float vFadeShare;  // fading from its last mesh level: the impostor's share
layout(location = 9) flat out uint vBandStep;   // impostorBlend's step from the lower band's cells to the upper's

void main() {
    const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
    uint index = impostors[gl_VertexIndex / 4];
    CharacterRecord character = characters[index];
    ImpostorQuad q = impostorQuad(character, impostorModelOf(character), cameraPosition.xyz, SHADOW_PASS,
                                  scene.lightDirection.xyz);
    if (!BLEND) q.blend = impostorNearest(q.blend);
    else if (SHADOW_PASS) q.blend = impostorNearestBand(q.blend);
    vec2 corner = corners[gl_VertexIndex % 4];
    vec3 world = impostorCorner(q, corner);
    gl_Position = scene.viewProjection * vec4(world, 1.0);
    vLocal = impostorLocal(corner);
    vCells = q.blend.cells;
    vWeights = q.blend.weights;
    vBandStep = q.blend.bandStep;
    vGrid = q.grid;
    vTint = character.tint.rgb;
    vHeading = q.heading;
    vWorld = world;
    vRadius = q.halfSide;
    vFadeShare = fadeShareOf(characterStates[index]);
}
