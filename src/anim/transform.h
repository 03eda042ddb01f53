#pragma once
// A joint's local transform as translation, rotation and scale (the glTF decomposition).
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace anim {

struct Transform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
    glm::vec3 scale{1.0f};

    // The matrix T * R * S, as glTF composes a node's local transform.
    glm::mat4 matrix() const;
};

}  // namespace anim
