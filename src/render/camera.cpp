#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace render {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)); }

glm::mat4 Camera::projection(float aspect) const {
    glm::mat4 projection = glm::perspective(verticalFov, aspect, nearPlane, farPlane);
    projection[1][1] *= -1.0f;  // Vulkan's y axis points down
    return projection;
}

Camera frameCrowd(const glm::vec3& center, float radius, float characterHeight, float aspect) {
    Camera camera;
    const float r = std::max(radius, characterHeight);
    // A three-quarter view from above (about 30 degrees down), so characters show their profile,
    // from just far enough that the crowd's square fills most of the narrower side of the image.
    const float halfFov = 0.5f * camera.verticalFov * std::min(1.0f, aspect);
    const float distance = r / std::tan(halfFov) * 0.72f + 1.5f * characterHeight;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.55f, 0.6f, 1.0f));
    camera.target = center + glm::vec3(0.0f, 0.45f * characterHeight, 0.0f);
    camera.eye = camera.target + direction * distance;
    camera.nearPlane = std::max(0.05f, distance * 0.01f);
    camera.farPlane = distance * 4.0f + r * 4.0f;
    return camera;
}

}  // namespace render
