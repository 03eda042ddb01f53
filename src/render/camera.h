#pragma once
// A perspective camera looking at a point.
#include <glm/glm.hpp>

namespace render {

struct Camera {
    glm::vec3 eye{0.0f, 10.0f, 20.0f};
    glm::vec3 target{0.0f};
    float verticalFov = 0.7f;  // radians
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;

    glm::mat4 view() const;
    // Vulkan clip space: y down, depth 0..1 (near 0).
    glm::mat4 projection(float aspect) const;
    glm::mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }
};

// A camera in front of (+z) and above a crowd of this centre and radius, framing all of it.
Camera frameCrowd(const glm::vec3& center, float radius, float characterHeight, float aspect);

}  // namespace render
