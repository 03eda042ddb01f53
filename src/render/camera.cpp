#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace render {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)); }

glm::mat4 Camera::projection(float aspect) const {
    glm::mat4 projection = glm::perspective(verticalFov, aspect, nearPlane, farPlane);
    projection[1][1] *= -1.0f;  // Vulkan's y axis points down
    return projection;
}

}  // namespace render
