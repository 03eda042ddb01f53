#include "model/influences.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace model {
namespace {

// Arc length along the chain of the point's projection; before the first joint and after the last
// the end bones extend in a straight line, so every point has a place on the chain.
float arcPosition(const BoneChain& chain, const glm::vec3& point) {
    const std::size_t bones = chain.positions.size() - 1;
    float best = std::numeric_limits<float>::max(), arc = 0.0f, start = 0.0f;
    for (std::size_t k = 0; k < bones; ++k) {
        const glm::vec3 a = chain.positions[k], d = chain.positions[k + 1] - a;
        const float length = glm::length(d);
        float t = glm::dot(point - a, d) / (length * length);
        t = std::min(t, k + 1 == bones ? std::numeric_limits<float>::max() : 1.0f);
        t = std::max(t, k == 0 ? std::numeric_limits<float>::lowest() : 0.0f);
        const float distance = glm::length(point - (a + t * d));
        if (distance < best) best = distance, arc = start + t * length;
        start += length;
    }
    return arc;
}

}  // namespace

Influences rigid(std::uint32_t joint) {
    Influences influences;
    influences.joints.x = joint;
    influences.weights.x = 1.0f;
    return influences;
}

Influences chainInfluences(const BoneChain& chain, const glm::vec3& point, float band) {
    assert(!chain.joints.empty() && chain.joints.size() == chain.positions.size());
    if (chain.joints.size() == 1) return rigid(chain.joints[0]);
    const float s = arcPosition(chain, point);
    float jointArc = 0.0f;
    for (std::size_t k = 1; k < chain.joints.size(); ++k) {
        const float before = glm::distance(chain.positions[k - 1], chain.positions[k]);
        const float after = k + 1 < chain.joints.size()
                                ? glm::distance(chain.positions[k], chain.positions[k + 1])
                                : std::numeric_limits<float>::max();
        jointArc += before;
        // 0.45 of the shorter bone keeps neighbouring blend bands from overlapping.
        const float halfBand = std::min({band, 0.45f * before, 0.45f * after});
        if (s >= jointArc + halfBand) continue;
        if (s <= jointArc - halfBand) return rigid(chain.joints[k - 1]);
        const float child = glm::smoothstep(jointArc - halfBand, jointArc + halfBand, s);
        Influences influences;
        influences.joints = {chain.joints[k - 1], chain.joints[k], 0u, 0u};
        influences.weights = {1.0f - child, child, 0.0f, 0.0f};
        return influences;
    }
    return rigid(chain.joints.back());
}

}  // namespace model
