#include "model/skeleton_builder.h"

#include <cassert>

#include <glm/gtc/matrix_transform.hpp>

namespace model {

std::uint32_t SkeletonBuilder::add(std::string name, std::int32_t parent, glm::vec3 position) {
    assert(parent < static_cast<std::int32_t>(parents_.size()));
    names_.push_back(std::move(name));
    parents_.push_back(parent);
    positions_.push_back(position);
    return static_cast<std::uint32_t>(parents_.size() - 1);
}

std::vector<glm::vec3> SkeletonBuilder::positions(const std::vector<std::uint32_t>& joints) const {
    std::vector<glm::vec3> result;
    for (std::uint32_t joint : joints) result.push_back(positions_[joint]);
    return result;
}

anim::Skeleton SkeletonBuilder::build(glm::vec3 stretch) const {
    anim::Skeleton skeleton;
    skeleton.jointNames = names_;
    skeleton.parents = parents_;
    for (std::size_t i = 0; i < parents_.size(); ++i) {
        const glm::vec3 global = positions_[i] * stretch;
        const glm::vec3 above = parents_[i] < 0 ? glm::vec3(0.0f) : positions_[parents_[i]] * stretch;
        anim::Transform rest;
        rest.translation = global - above;
        skeleton.restPose.push_back(rest);
        skeleton.inverseBind.push_back(glm::translate(glm::mat4(1.0f), -global));
    }
    return skeleton;
}

}  // namespace model
