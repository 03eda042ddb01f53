#pragma once
// A joint hierarchy: parents, rest pose and inverse bind matrices.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/transform.h"

namespace anim {

struct Skeleton {
    std::vector<std::string> jointNames;
    // parents[i] < i for every joint, -1 for roots: one forward sweep computes the hierarchy.
    std::vector<std::int32_t> parents;
    // Local transform of each joint when no clip animates it.
    std::vector<Transform> restPose;
    // Model space to joint space at bind time.
    std::vector<glm::mat4> inverseBind;
    // Transform of whatever sits above the root joints (glTF nodes above the skeleton).
    glm::mat4 rootTransform{1.0f};
    // Per joint: 0 for the body's joints, k + 1 for the joint that carries the model's prop k
    // (model/attach_prop.h). A character that does not carry prop k gets that joint's bone collapsed to
    // a point (anim/props_carried.h). Empty: the model has no props.
    std::vector<std::uint32_t> propOfJoint;

    std::size_t jointCount() const { return parents.size(); }
};

}  // namespace anim
