#include "anim/props_carried.h"

namespace anim {

Affine collapsedBone(glm::vec3 jointWorldPosition) {
    return {glm::vec4(0.0f, 0.0f, 0.0f, jointWorldPosition.x), glm::vec4(0.0f, 0.0f, 0.0f, jointWorldPosition.y),
            glm::vec4(0.0f, 0.0f, 0.0f, jointWorldPosition.z)};
}

void collapseUncarriedProps(std::span<const std::uint32_t> propOfJoint, std::uint32_t carried,
                            std::span<const Affine> world, std::span<gpu::BoneRows> bones) {
    for (std::size_t j = 0; j < propOfJoint.size(); ++j)
        if (!jointCarried(propOfJoint[j], carried))
            bones[j] = collapsedBone({world[j].row0.w, world[j].row1.w, world[j].row2.w});
}

}  // namespace anim
