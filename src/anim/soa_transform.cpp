#include "anim/soa_transform.h"

#include <cassert>

namespace anim {

Transform soaLane(const SoaTransform& g, std::size_t i) {
    return {{g.translation.x[i], g.translation.y[i], g.translation.z[i]},
            glm::quat(g.rotation.w[i], g.rotation.x[i], g.rotation.y[i], g.rotation.z[i]),
            {g.scale.x[i], g.scale.y[i], g.scale.z[i]}};
}

void setSoaLane(SoaTransform& g, std::size_t i, const Transform& t) {
    g.translation.x[i] = t.translation.x, g.translation.y[i] = t.translation.y, g.translation.z[i] = t.translation.z;
    g.rotation.x[i] = t.rotation.x, g.rotation.y[i] = t.rotation.y, g.rotation.z[i] = t.rotation.z;
    g.rotation.w[i] = t.rotation.w;
    g.scale.x[i] = t.scale.x, g.scale.y[i] = t.scale.y, g.scale.z[i] = t.scale.z;
}

void toSoa(std::span<const Transform> aos, std::span<SoaTransform> soa) {
    assert(soa.size() >= soaGroups(aos.size()));
    for (std::size_t j = 0; j < soaGroups(aos.size()) * kSoaLanes; ++j)
        setSoaLane(soa[j / kSoaLanes], j % kSoaLanes, j < aos.size() ? aos[j] : Transform{});
}

void fromSoa(std::span<const SoaTransform> soa, std::span<Transform> aos) {
    assert(soa.size() >= soaGroups(aos.size()));
    for (std::size_t j = 0; j < aos.size(); ++j) aos[j] = soaLane(soa[j / kSoaLanes], j % kSoaLanes);
}

}  // namespace anim
