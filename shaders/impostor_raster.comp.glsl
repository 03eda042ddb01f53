#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The compute rasterizer of impostors (docs/compute-raster.md): each thread takes impostors of the
// frame's list in turn, finds its quad's screen rectangle, and for each pixel centre on the quad tests
// the atlas's blended coverage as the hardware path's fragment shader does (cut under half) and keeps
// depth | list index with a 64-bit atomic min in the visibility buffer; impostor_resolve.frag.glsl
// shades the winners. An impostor larger on screen than the push constants allow, or crossing the
// near plane, is listed for the hardware path instead (ImpostorSplit).
#include "gpu_types.h"
#include "impostor_pose.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_quad.glsl.inc"
#include "impostor_raster_pixel.glsl.inc"
#include "impostor_sample.glsl.inc"

layout(local_size_x = IMPOSTOR_RASTER_WORKGROUP) in;

layout(push_constant) uniform Push { ImpostorRasterPush raster; };
layout(std430, set = 0, binding = 0) readonly buffer ImpostorModels { ImpostorModel impostorModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 2) readonly buffer Impostors { uint impostors[]; };
layout(std430, set = 0, binding = 3) readonly buffer Frame { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 4) buffer Visibility { uint64_t visibility[]; };
layout(std430, set = 0, binding = 5) buffer Split { ImpostorSplit split; };
layout(std430, set = 0, binding = 6) writeonly buffer HardwareImpostors { uint hardwareImpostors[]; };
layout(set = 1, binding = 0) uniform sampler2DArray atlasAlbedo;

// Impostors this workgroup rasterized: summed in shared memory and added to the split once per
// workgroup, since millions of atomics on one word would serialize (a few ms for 10,000,000 on one
// address); the rare hardware-bound impostors take the global atomic directly.
shared uint rasterized;

// The quad's screen rectangle in pixels (viewport-relative); false when a corner is at or behind the
// eye's plane (the hardware path clips such a quad).
bool screenRectangle(ImpostorQuadClip k, out vec2 low, out vec2 high) {
    const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
    low = vec2(3.0e38);
    high = vec2(-3.0e38);
    for (int i = 0; i < 4; ++i) {
        vec4 clip = impostorClipAt(k, corners[i]);
        if (!(clip.w > 0.0)) return false;
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * raster.viewport.xy;
        low = min(low, pixel);
        high = max(high, pixel);
    }
    return true;
}

// Returns whether the impostor was rasterized here (not left to the hardware).
bool rasterize(uint index) {
    uint character = impostors[index];
    CharacterRecord record = characters[character];
    ImpostorModel m = impostorModels[record.ids.x];
    ImpostorQuad q = impostorQuad(record, m, raster.cameraPosition.xyz, false, vec3(0.0));
    ImpostorQuadClip k = impostorQuadClip(q, raster.viewProjection);
    vec2 low, high;
    if (!screenRectangle(k, low, high) || max(high.x - low.x, high.y - low.y) > raster.viewport.z) {
        hardwareImpostors[atomicAdd(split.hardwareCount, 1u)] = character;
        return false;
    }
    // Pixels whose centre (x + 0.5, y + 0.5) lies in the rectangle, inside the viewport.
    ivec2 extent = ivec2(raster.viewport.xy);
    ivec2 first = max(ivec2(ceil(low - 0.5)), ivec2(0));
    ivec2 last = min(ivec2(floor(high - 0.5)), extent - 1);
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            ImpostorPixel p = impostorPixel(k, vec2(x, y), raster.viewport.xy);
            if (!p.inside) continue;
            impostorUseGradients(p, q.grid);
            if (impostorBlendedTexel(atlasAlbedo, q.blend.cells, q.blend.weights, q.grid, p.local).a < 0.5) continue;
            uint64_t word = (uint64_t(floatBitsToUint(p.depth)) << 32) | uint64_t(index);
            atomicMin(visibility[uint(y) * uint(extent.x) + uint(x)], word);
        }
    return true;
}

void main() {
    if (gl_LocalInvocationIndex == 0u) rasterized = 0u;
    barrier();
    uint count = min(impostorFrame.count, raster.limits.x);
    uint mine = 0u;
    for (uint index = gl_GlobalInvocationID.x; index < count; index += raster.limits.y)
        mine += rasterize(index) ? 1u : 0u;
    if (mine > 0u) atomicAdd(rasterized, mine);
    barrier();
    if (gl_LocalInvocationIndex == 0u && rasterized > 0u) atomicAdd(split.computeCount, rasterized);
}
