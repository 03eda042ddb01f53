#version 460
// The compute-rasterized shadow map's depths (shadow_raster.comp.glsl: one word a texel, a float's
// bits, so that a 32-bit atomic min is the depth test) converted to the map's 16-bit unorm texels, two
// a word, for the copy into the D16 map (render/shadow_map.h says why 16 bits). Round to nearest, as
// the hardware's conversion of a fragment's depth into a unorm attachment does; a map with an odd
// count of texels leaves the last word's upper half at the far plane, which the copy does not read.
layout(local_size_x = 256) in;

layout(push_constant) uniform Push { uint texels; };
layout(std430, set = 0, binding = 0) readonly buffer Depth { uint depth[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Packed { uint packedTexels[]; };

uint unorm16(uint bits) { return uint(round(clamp(uintBitsToFloat(bits), 0.0, 1.0) * 65535.0)); }

void main() {
    // A stride over the words: a 16384-texel map has more of them than one dispatch's workgroups.
    const uint words = texels / 2u + texels % 2u;
    for (uint w = gl_GlobalInvocationID.x; w < words; w += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {
        const uint low = unorm16(depth[2u * w]);
        const uint high = 2u * w + 1u < texels ? unorm16(depth[2u * w + 1u]) : 0xFFFFu;
        packedTexels[w] = low | (high << 16);
    }
}
