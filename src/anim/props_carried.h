#pragma once
// Props a character does not carry. A prop is part of its model's mesh, moved by a joint of its own
// (model/attach_prop.h); a character that does not carry it gets that joint's bone collapsed to the
// joint's position: every vertex of the prop lands on one point, its triangles have no area and draw
// no pixel in any pass, and every skinning method (which all read the same bones) agrees. The GPU's
// palette pass does the same (shaders/palette.comp.glsl).
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "anim/affine.h"

namespace anim {

// Whether a character whose mask is `carried` carries the prop of a joint whose propOfJoint entry is
// `propOfJoint` (0: a body joint, always carried).
inline bool jointCarried(std::uint32_t propOfJoint, std::uint32_t carried) {
    return propOfJoint == 0u || (carried >> (propOfJoint - 1u) & 1u) != 0u;
}

// The bone of a prop left behind: no rotation or scale, the translation the joint's world position.
Affine collapsedBone(glm::vec3 jointWorldPosition);

// Replaces the bones of the props not in `carried` by collapsedBone at their joints' world positions
// (`world`: each joint's world transform, as the palette jobs leave them). `propOfJoint` empty: none.
void collapseUncarriedProps(std::span<const std::uint32_t> propOfJoint, std::uint32_t carried,
                            std::span<const Affine> world, std::span<gpu::BoneRows> bones);

}  // namespace anim
