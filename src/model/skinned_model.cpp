#include "model/skinned_model.h"

#include <limits>

namespace model {

int SkinnedModel::findClip(const std::string& clipName) const {
    for (std::size_t i = 0; i < clips.size(); ++i)
        if (clips[i].name == clipName) return static_cast<int>(i);
    return -1;
}

void computeBounds(SkinnedModel& model) {
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    const std::vector<std::uint32_t>& propOfJoint = model.skeleton.propOfJoint;
    bool any = false;
    for (const gpu::SkinVertex& v : model.vertices) {
        // The body's bounds: a prop (a flag's pole) does not make the character taller or wider.
        if (v.joints.x < propOfJoint.size() && propOfJoint[v.joints.x] != 0u) continue;
        any = true;
        lo = glm::min(lo, glm::vec3(v.position));
        hi = glm::max(hi, glm::vec3(v.position));
    }
    if (!any) lo = hi = glm::vec3(0.0f);
    model.boundsMin = lo;
    model.boundsMax = hi;
}

}  // namespace model
