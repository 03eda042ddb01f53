#include "anim/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace anim {

glm::mat4 Transform::matrix() const {
    glm::mat4 m = glm::mat4_cast(rotation);
    m[0] *= scale.x;
    m[1] *= scale.y;
    m[2] *= scale.z;
    m[3] = glm::vec4(translation, 1.0f);
    return m;
}

}  // namespace anim
