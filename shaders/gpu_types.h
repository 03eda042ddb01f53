// GPU-visible data layouts, declared once and included by both C++ and GLSL.
// Every struct here uses only 16-byte members so std430 / std140 / C++ layouts agree;
// gpu_types_check.cpp static_asserts the sizes and offsets on the C++ side.
#ifndef CROWD_GPU_TYPES_H
#define CROWD_GPU_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#endif

// Most influences a vertex can have; the loaders reduce to the 4 largest.
#define MAX_INFLUENCES 4
// Characters' material colours live in a small palette in SceneUniforms.
#define MAX_MATERIALS 16

// One bind-pose vertex as pass 1 (and the vertex-shader baseline) reads it.
// normal.w holds the vertex's material index (a small integer stored exactly as a float).
struct SkinVertex {
    vec4 position;  // xyz model space, w = 1
    vec4 normal;    // xyz unit normal, w = material index
    uvec4 joints;   // 4 joint indices into the character's bone block
    vec4 weights;   // 4 weights, summing to 1
};

// One skinning matrix as three rows of a 3x4 affine matrix: row i dotted with (p, 1) gives
// coordinate i. The paper keeps each row in its own RGBA32F texture; we keep the three rows
// of a bone next to each other in one buffer so a fetch of one bone touches one 48-byte line.
struct BoneRows {
    vec4 row0;
    vec4 row1;
    vec4 row2;
};

// Push constants of the fragment skinning pass (pass 1).
struct SkinPassParams {
    // x: characters in this target, y: vertices per character,
    // z: rows per character, w: first character of this target
    uvec4 counts;
    // x: target width in texels, y: bone block stride in BoneRows, z, w: unused
    uvec4 strides;
};

// Per-frame uniforms of the draw pass (pass 2), the ground and the vertex-shader baseline.
struct SceneUniforms {
    mat4 viewProjection;
    vec4 lightDirection;  // xyz: unit vector towards the light, w: ambient term
    vec4 skyColor;
    vec4 groundColor;     // xyz colour, w: checker tile size in metres
    uvec4 materialFlags;  // x: bit m set when material m is multiplied by the base-colour texture
    vec4 palette[MAX_MATERIALS];
};

#ifdef __cplusplus
}  // namespace gpu
#endif
#endif
