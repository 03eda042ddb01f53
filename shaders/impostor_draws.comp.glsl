#version 460
#extension GL_GOOGLE_include_directive : require
// After culling: the impostor level's indexed draws. One fixed index buffer holds
// IMPOSTOR_QUADS_PER_DRAW quads (four vertices, six indices each: vertices are shared, which the
// draw's cost follows); draw k covers impostors k x IMPOSTOR_QUADS_PER_DRAW onwards through its
// vertexOffset, so the vertex shader's gl_VertexIndex / 4 is the impostor.
#include "gpu_types.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Frame { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 1) writeonly buffer Draws {
    ImpostorDrawsHeader header;
    DrawIndexedCommand draws[];
};

void main() {
    uint count = impostorFrame.count;
    uint drawCount = (count + IMPOSTOR_QUADS_PER_DRAW - 1u) / IMPOSTOR_QUADS_PER_DRAW;
    if (gl_LocalInvocationIndex == 0u) header = ImpostorDrawsHeader(drawCount, 0u, 0u, 0u);
    for (uint k = gl_LocalInvocationIndex; k < drawCount; k += 64u) {
        uint quads = min(count - k * IMPOSTOR_QUADS_PER_DRAW, IMPOSTOR_QUADS_PER_DRAW);
        draws[k] = DrawIndexedCommand(6u * quads, 1u, 0u, int(4u * k * IMPOSTOR_QUADS_PER_DRAW), 0u);
    }
}
