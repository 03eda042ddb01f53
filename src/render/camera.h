#pragma once
// A perspective camera looking at a point, and the crowd it looks at.
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

// Where a crowd stands and how big its characters are (the shadow map's fit).
struct CrowdShape {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float characterHeight = 1.0f;
    float ground = 0.0f;  // the lowest the ground goes (the terrain's lowest height; 0 without terrain)
};

}  // namespace render
