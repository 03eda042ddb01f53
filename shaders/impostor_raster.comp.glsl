#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The compute rasterizer of impostors (docs/compute-raster.md). First dispatch: each thread takes
// impostors of the frame's list in turn and finds its quad's screen rectangle. An impostor larger on
// screen than the push constants allow, or crossing the eye's plane, is listed for the hardware path
// (ImpostorSplit); one larger than a thread should walk alone is listed for the second dispatch
// (LARGE_PASS, indirect: a workgroup an impostor, its threads striding over the rectangle); the rest
// the thread draws itself. Drawing a pixel: a pixel centre on the quad is tested against the atlas's
// blended coverage as the hardware path's fragment shader does (cut under half) and depth | list index
// is kept with a 64-bit atomic min in the visibility buffer; impostor_resolve.frag.glsl shades the winners.
// An impostor no larger than raster.far.x (the far crowd) is added to the far layer by its coverage
// instead (far_crowd.glsl.inc), which far_crowd_resolve.frag.glsl lights and blends; one under
// raster.far.y pixels is left to the third dispatch (SPLAT_PASS), which splats it.
#include "gpu_types.h"
#include "impostor_pose.glsl.inc"
#include "impostor_cell.glsl.inc"
#include "impostor_quad.glsl.inc"
#include "impostor_raster_pixel.glsl.inc"
#include "impostor_sample.glsl.inc"
#include "impostor_normal.glsl.inc"
#include "fade_dither.glsl.inc"

layout(local_size_x = IMPOSTOR_RASTER_WORKGROUP) in;
// Which dispatch: the list's impostors (MAIN_PASS), the large ones it listed (LARGE_PASS), or the far
// layer's splats (SPLAT_PASS: the list again, taking only those).
const uint MAIN_PASS = 0u, LARGE_PASS = 1u, SPLAT_PASS = 2u;
layout(constant_id = 0) const uint RASTER_PASS = MAIN_PASS;

layout(push_constant) uniform Push { ImpostorRasterPush raster; };
layout(std430, set = 0, binding = 0) readonly buffer ImpostorModels { ImpostorModel impostorModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 2) readonly buffer Impostors { uint impostors[]; };
layout(std430, set = 0, binding = 3) readonly buffer Frame { ImpostorFrame impostorFrame; };
layout(std430, set = 0, binding = 4) buffer Visibility { uint64_t visibility[]; };
layout(std430, set = 0, binding = 5) buffer Split { ImpostorSplit split; };
layout(std430, set = 0, binding = 6) writeonly buffer HardwareImpostors { uint hardwareImpostors[]; };
layout(std430, set = 0, binding = 7) buffer LargeImpostors { uint largeImpostors[]; };
// Every character's state word (gpu_types.h: its fade share, FADE_SHIFT), written by culling.
layout(std430, set = 0, binding = 8) readonly buffer CharacterStates { uint characterStates[]; };
// The far layer (its depth words and sums, gpu_types.h: FAR_CROWD_*); bound to the visibility buffer
// when far-crowd is off (never written then).
layout(std430, set = 0, binding = 9) buffer FarDepth { uint64_t farDepth[]; };
layout(std430, set = 0, binding = 10) buffer FarSums { uint64_t farSums[]; };  // 32-bit sums in pairs
layout(set = 1, binding = 0) uniform sampler2DArray atlasAlbedo;
// The same with every level of the mip chain, for the far layer's smallest impostors (far_crowd.glsl.inc, farUseGradients).
layout(set = 1, binding = 2) uniform sampler2DArray atlasAlbedoWhole;
layout(set = 1, binding = 3) uniform sampler2DArray atlasNormalWhole;
#include "impostor_prop_set.glsl.inc"
#include "far_crowd.glsl.inc"

// Impostors this workgroup rasterized: summed in shared memory and added to the split once per
// workgroup, since millions of atomics on one word would serialize (a few ms for 10,000,000 on one
// address); the rare hardware-bound and large impostors take global atomics directly.
shared uint rasterized, averaged;

struct Footprint {
    ImpostorQuad quad;
    ImpostorQuadClip clip;
    vec2 low, high;     // the screen rectangle, pixels
    ivec2 first, last;  // pixels whose centre lies in the screen rectangle, inside the viewport
    float side;         // the rectangle's longer side, pixels
    bool visible;       // no corner at or behind the eye's plane (the hardware path clips such a quad)
};

Footprint footprint(uint index) {
    const vec2 corners[4] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, 1));
    Footprint f;
    CharacterRecord record = characters[impostors[index]];
    f.quad = impostorQuad(record, impostorModelOf(record), raster.cameraPosition.xyz, false, vec3(0.0));
    if (raster.limits.w == 0u) f.quad.blend = impostorNearest(f.quad.blend);
    f.clip = impostorQuadClip(f.quad, raster.viewProjection);
    vec2 low = vec2(3.0e38), high = vec2(-3.0e38);
    f.visible = true;
    for (int i = 0; i < 4; ++i) {
        vec4 clip = impostorClipAt(f.clip, corners[i]);
        f.visible = f.visible && clip.w > 0.0;
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * raster.viewport.xy;
        low = min(low, pixel);
        high = max(high, pixel);
    }
    f.low = low;
    f.high = high;
    f.side = max(high.x - low.x, high.y - low.y);
    f.first = max(ivec2(ceil(low - 0.5)), ivec2(0));
    f.last = min(ivec2(floor(high - 0.5)), ivec2(raster.viewport.xy) - 1);
    return f;
}

// Pixels start, start + stride, ... of the footprint's rectangle (row by row).
void drawPixels(uint index, Footprint f, uint start, uint stride) {
    if (any(greaterThan(f.first, f.last))) return;
    uint width = uint(f.last.x - f.first.x + 1), count = width * uint(f.last.y - f.first.y + 1);
    uint rowPitch = uint(raster.viewport.x);
    // Fading from its last mesh level: only the impostor's share of the dither (the hardware path's
    // fragment shader drops the same pixels; the mask is the viewport's, a multiple of 4 pixels from the
    // target's origin in the programs).
    float fadeShare = fadeShareOf(characterStates[impostors[index]]);
    bool blend = raster.limits.w != 0u;
    for (uint p = start; p < count; p += stride) {
        ivec2 at = f.first + ivec2(p % width, p / width);
        if (fadeShare > 0.0 && !fadeDraws(vec2(at) + 0.5, fadeShare, true)) continue;
        ImpostorPixel pixel = impostorPixel(f.clip, vec2(at), raster.viewport.xy);
        if (!pixel.inside) continue;
        impostorUseGradients(pixel, f.quad.grid);
        if (impostorTexel(atlasAlbedo, blend, f.quad.blend, f.quad.grid, pixel.local).a < 0.5)
            continue;
        uint64_t word = (uint64_t(floatBitsToUint(pixel.depth)) << 32) | uint64_t(index);
        atomicMin(visibility[uint(at.y) * rowPitch + uint(at.x)], word);
    }
}

// How the impostor was drawn: by the hardware path, in compute (here or in the second dispatch),
// averaged into the far layer, splatted into it (by the third dispatch), or, in the third, by another.
const uint TAKEN_HARDWARE = 0u, TAKEN_COMPUTE = 1u, TAKEN_AVERAGED = 2u, TAKEN_SPLATTED = 3u, TAKEN_ELSEWHERE = 4u;

bool forHardware(Footprint f) { return !f.visible || f.side > raster.viewport.z; }

// A fading impostor keeps its dithered pixels (the mesh draws the others), so it is never averaged.
bool joinsFarLayer(uint index, Footprint f) {
    return f.side <= raster.far.x && fadeShareOf(characterStates[impostors[index]]) == 0.0;
}

uint take(uint index) {
    Footprint f = footprint(index);
    if (forHardware(f)) {
        hardwareImpostors[atomicAdd(split.hardwareCount, 1u)] = impostors[index];
        return TAKEN_HARDWARE;
    }
    if (joinsFarLayer(index, f)) {
        if (f.side < raster.far.y) return TAKEN_SPLATTED;
        CharacterRecord record = characters[impostors[index]];
        averagePixels(index, f.quad, f.clip, f.low, f.high, f.side, record.tint.rgb, raster.limits.w != 0u,
                      raster.viewport.xy);
        return TAKEN_AVERAGED;
    }
    if (f.side > raster.viewport.w) {
        uint slot = atomicAdd(split.largeCount, 1u);
        if (slot < raster.limits.z) {
            largeImpostors[slot] = index;
            atomicMax(split.largeDispatch.x, slot + 1u);
            return TAKEN_COMPUTE;
        }
    }
    drawPixels(index, f, 0u, 1u);
    return TAKEN_COMPUTE;
}

// The splats' dispatch: the impostors take() left to it, found again by the same tests.
uint splat(uint index) {
    Footprint f = footprint(index);
    if (forHardware(f) || !joinsFarLayer(index, f) || f.side >= raster.far.y) return TAKEN_ELSEWHERE;
    CharacterRecord record = characters[impostors[index]];
    splatPixels(index, f.quad, f.clip, f.low, f.high, record.tint.rgb, raster.limits.w != 0u, raster.viewport.xy,
                int(raster.far.z));
    return TAKEN_SPLATTED;
}

void main() {
    if (RASTER_PASS == LARGE_PASS) {
        uint index = largeImpostors[gl_WorkGroupID.x];
        drawPixels(index, footprint(index), gl_LocalInvocationIndex, IMPOSTOR_RASTER_WORKGROUP);
        return;
    }
    if (gl_LocalInvocationIndex == 0u) rasterized = 0u, averaged = 0u;
    barrier();
    uint count = min(impostorFrame.count, raster.limits.x);
    uint mine = 0u, mineAveraged = 0u;
    for (uint index = gl_GlobalInvocationID.x; index < count; index += raster.limits.y) {
        // Each splat is counted by the dispatch that draws it.
        uint taken = RASTER_PASS == SPLAT_PASS ? splat(index) : take(index);
        bool drawnHere = RASTER_PASS == SPLAT_PASS ? taken == TAKEN_SPLATTED : taken == TAKEN_COMPUTE || taken == TAKEN_AVERAGED;
        mine += drawnHere ? 1u : 0u;
        mineAveraged += drawnHere && taken != TAKEN_COMPUTE ? 1u : 0u;
    }
    if (mine > 0u) atomicAdd(rasterized, mine);
    if (mineAveraged > 0u) atomicAdd(averaged, mineAveraged);
    barrier();
    if (gl_LocalInvocationIndex == 0u && rasterized > 0u) atomicAdd(split.computeCount, rasterized);
    if (gl_LocalInvocationIndex == 0u && averaged > 0u) atomicAdd(split.averagedCount, averaged);
}
