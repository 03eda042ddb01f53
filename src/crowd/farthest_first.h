#pragma once
// The mesh-level cap's rule, farthest first: when more characters qualify for a mesh level (LOD 0-2) than
// the cap allows, the cap's worth with the largest projected size keep their meshes and the rest are
// demoted to impostors. Ranked by size, larger first; among exactly equal sizes, by character index,
// lower first. So the mesh levels hold exactly the cap, and no demoted character is larger on screen
// than a kept one. The CPU reference (cull_reference.h) applies it; the GPU reaches the same choice with
// histograms (shaders/mesh_cut.glsl.inc).
#include <cstdint>
#include <span>
#include <vector>

namespace crowd {

struct SizedCharacter {
    std::uint32_t character;
    float size;  // projected diameter in pixels, never negative
};

// Per candidate, in the order given: whether it keeps its mesh level.
std::vector<bool> keepsMesh(std::span<const SizedCharacter> candidates, std::uint32_t capacity);

}  // namespace crowd
