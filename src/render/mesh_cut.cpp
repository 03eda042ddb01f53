#include "render/mesh_cut.h"

#include "gpu_types.h"

namespace render {

MeshCutSizes meshCutSizes(std::uint64_t characters, std::uint32_t meshCapacity) {
    MeshCutSizes sizes;
    if (meshCapacity == 0) {
        sizes.histograms = sizeof(gpu::MeshCut) + 4;
        sizes.candidates = 8;
        sizes.boundary = 4;
        return sizes;
    }
    // Every character may qualify for a mesh level, and all may share the cut's coarse bucket.
    sizes.histograms = sizeof(gpu::MeshCut) + std::uint64_t{MESH_CUT_COARSE_BUCKETS + MESH_CUT_FINE_BUCKETS} * 4;
    sizes.tieBits = (characters + 31) / 32 * 4;
    sizes.candidates = characters * 8;
    sizes.boundary = characters * 4;
    return sizes;
}

}  // namespace render
