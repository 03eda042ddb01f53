#pragma once
// Builds a bind-pose skeleton from joints placed in model space.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/skeleton.h"

namespace model {

// Procedural characters are modelled standing in their rest pose, so every joint's rest rotation is
// the identity and its bind matrix is a pure translation to where it was placed.
class SkeletonBuilder {
public:
    // Adds a joint at a model-space position under `parent` (-1 for the root); returns its index.
    // Parents must be added first, which keeps parents[i] < i.
    std::uint32_t add(std::string name, std::int32_t parent, glm::vec3 position);

    glm::vec3 position(std::uint32_t joint) const { return positions_[joint]; }
    std::vector<glm::vec3> positions(const std::vector<std::uint32_t>& joints) const;

    // The skeleton with every position scaled per axis by `stretch` (the seed's proportions).
    anim::Skeleton build(glm::vec3 stretch) const;

private:
    std::vector<std::string> names_;
    std::vector<std::int32_t> parents_;
    std::vector<glm::vec3> positions_;
};

}  // namespace model
