#pragma once
// The buffers of the mesh-level cap's cut, farthest first (shaders/mesh_cut.glsl.inc, gpu::MeshCut):
// sized for the crowd when a cap is in effect, one element each when not (they are bound all the same).
// Sized here, before anything is allocated, so that frame::planMemory counts what DrawLists makes.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace render {

struct MeshCutSizes {
    VkDeviceSize histograms = 0;  // gpu::MeshCut, then the coarse and fine size histograms: fixed
    VkDeviceSize tieBits = 0;     // one bit per character, after the histograms in the same buffer
    VkDeviceSize candidates = 0;  // a candidate (character, size key) per character
    VkDeviceSize boundary = 0;    // an index into the candidates per character (the cut's coarse bucket)
    VkDeviceSize cutBuffer() const { return histograms + tieBits; }
    VkDeviceSize total() const { return cutBuffer() + candidates + boundary; }
};

// `meshCapacity`: the cap in effect (0: none).
MeshCutSizes meshCutSizes(std::uint64_t characters, std::uint32_t meshCapacity);

}  // namespace render
