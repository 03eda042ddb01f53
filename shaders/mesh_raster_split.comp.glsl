#version 460
#extension GL_GOOGLE_include_directive : require
// Which of the frame's mesh draws the compute rasterizer takes (docs/compute-raster.md, "Meshes"): a
// thread per command of the colour pass's compacted list. A character whose pose sphere is smaller on
// screen than the limit and lies wholly in front of the eye (so no triangle of it needs clipping at
// the eye's plane) is listed for mesh_raster.comp.glsl, and its colour command loses its instance, so
// the hardware draw skips it. Fading characters already have none (they are drawn from their own list,
// dithered, on the hardware) and stay there.
#include "gpu_types.h"
#include "cull.glsl.inc"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) buffer Draws { DrawIndexedCommand draws[]; };
layout(std430, set = 0, binding = 1) readonly buffer Totals { DrawTotals totals; };
layout(std430, set = 0, binding = 2) readonly buffer Models { ModelRecord models[]; };
layout(std430, set = 0, binding = 3) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 4) buffer Split { MeshSplit split; };
layout(std430, set = 0, binding = 5) writeonly buffer Listed { uint listed[]; };  // draws, by list place

layout(push_constant) uniform Push { MeshRasterPush push; };

// Nearer than this share of its radius beyond the eye's plane, a sphere's triangles may reach behind
// the eye, where a projected vertex is meaningless: the hardware clips those, so they stay there.
const float kNearMargin = 1.01;

void main() {
    const uint draw = gl_GlobalInvocationID.x;
    if (draw >= min(totals.drawCount, push.limits.z)) return;
    const DrawIndexedCommand command = draws[draw];
    if (command.instanceCount == 0u) return;
    const CharacterRecord character = characters[command.firstInstance];
    const vec4 sphere = worldSphere(character, models[character.ids.x]);
    const float w = (push.viewProjection * vec4(sphere.xyz, 1.0)).w;  // distance along the view axis
    if (w <= sphere.w * kNearMargin) return;
    if (projectedDiameter(sphere, push.camera) > push.viewport.z) return;
    const uint place = atomicAdd(split.computeCount, 1u);
    if (place >= push.limits.y) return;  // past what an id holds: the hardware draws it
    listed[place] = draw;
    draws[draw].instanceCount = 0u;
}
