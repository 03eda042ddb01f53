#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1 geometry: instance b is a rectangle over the rows of this target that hold bucket b's
// skinned vertex slots this frame (sized by culling's counts, read here on the GPU), so only visible
// characters are shaded. A bucket with nothing in this target collapses to an empty rectangle.
#include "gpu_types.h"

layout(push_constant) uniform Push { SkinPassParams params; };
layout(std430, set = 0, binding = 5) readonly buffer Buckets { BucketRecord buckets[]; };
layout(std430, set = 0, binding = 6) readonly buffer Frames { BucketFrame frames[]; };
layout(location = 0) flat out uint outBucket;

void main() {
    uint b = gl_InstanceIndex;
    uint width = params.target.x;
    uint start = frames[b].vertexBase;
    uint end = start + frames[b].count * buckets[b].mesh.z;
    int rows = int(params.target.z);
    int firstRow = clamp(int(start / width) - int(params.target.y), 0, rows);
    int lastRow = clamp(int((end + width - 1u) / width) - int(params.target.y), 0, rows);
    if (end == start) lastRow = firstRow;
    // Two triangles: corners (0,0) (1,0) (0,1) and (0,1) (1,0) (1,1).
    const uvec2 corners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(0, 1), uvec2(0, 1), uvec2(1, 0), uvec2(1, 1));
    uvec2 corner = corners[gl_VertexIndex];
    float y = float(corner.y == 0u ? firstRow : lastRow) / float(rows);
    gl_Position = vec4(float(corner.x) * 2.0 - 1.0, y * 2.0 - 1.0, 0.0, 1.0);
    outBucket = b;
}
