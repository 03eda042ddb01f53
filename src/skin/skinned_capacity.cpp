#include "skin/skinned_capacity.h"

#include <algorithm>
#include <vector>

#include "render/geometry_pool.h"

namespace skin {

SkinnedCapacity skinnedCapacity(const crowd::Crowd& crowd, std::uint32_t meshCapacity) {
    SkinnedCapacity result;
    std::uint64_t largestLod0 = 0;
    std::vector<std::vector<model::SkinnedModel::Lod>> lods;
    for (const model::SkinnedModel* m : crowd.models()) lods.push_back(render::lodsOf(*m));
    for (const crowd::Character& c : crowd.characters()) {
        result.perFrame += lods[c.model][0].vertexCount;
        for (const model::SkinnedModel::Lod& lod : lods[c.model]) result.fixed += lod.vertexCount;
    }
    for (const auto& l : lods) largestLod0 = std::max<std::uint64_t>(largestLod0, l[0].vertexCount);
    if (meshCapacity > 0 && meshCapacity < crowd.size()) {
        result.perFrame = std::min(result.perFrame, largestLod0 * meshCapacity);
        result.meshCapacity = meshCapacity;
    }
    return result;
}

}  // namespace skin
