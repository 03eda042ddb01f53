#version 460
#extension GL_GOOGLE_include_directive : require
// After culling: the impostor level's indexed draws. One fixed index buffer holds
// IMPOSTOR_QUADS_PER_DRAW quads (four vertices, six indices each: vertices are shared, which the
// draw's cost follows); draw k covers impostors k x IMPOSTOR_QUADS_PER_DRAW onwards through its
// vertexOffset, so the vertex shader's gl_VertexIndex / 4 is the impostor. The shadow pass's draws
// (from maxDraws on) cover the casting impostors, listed from `characters` on in the same list.
// The colour pass's count is the first word of binding 2: the impostor frame's count (every impostor
// in view), or, with the compute rasterizer (render/impostor_raster.h), the count of those it left to
// the hardware path (ImpostorSplit.hardwareCount), whose own list the colour draw then reads.
#include "gpu_types.h"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
    uint maxDraws;    // the colour pass's most draws: where the shadow pass's start
    uint characters;  // where the casting impostors start in the impostor list
};
layout(std430, set = 0, binding = 0) readonly buffer Frame { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 2) readonly buffer ColourCount { uint colourCount; };
layout(std430, set = 0, binding = 1) writeonly buffer Draws {
    ImpostorDrawsHeader header;
    DrawIndexedCommand draws[];
};

uint drawsFor(uint count) { return (count + IMPOSTOR_QUADS_PER_DRAW - 1u) / IMPOSTOR_QUADS_PER_DRAW; }

// Draws [first, first + drawsFor(count)) over `count` impostors listed from `listBase` on.
void writeDraws(uint first, uint count, uint listBase) {
    for (uint k = gl_LocalInvocationIndex; k < drawsFor(count); k += 64u) {
        uint quads = min(count - k * IMPOSTOR_QUADS_PER_DRAW, IMPOSTOR_QUADS_PER_DRAW);
        draws[first + k] = DrawIndexedCommand(6u * quads, 1u, 0u, int(4u * (listBase + k * IMPOSTOR_QUADS_PER_DRAW)), 0u);
    }
}

void main() {
    if (gl_LocalInvocationIndex == 0u)
        header = ImpostorDrawsHeader(drawsFor(colourCount), drawsFor(impostorFrame.shadowCount), 0u, 0u);
    writeDraws(0u, colourCount, 0u);
    writeDraws(maxDraws, impostorFrame.shadowCount, characters);
}
