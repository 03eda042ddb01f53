#include "app/camera.h"

#include <algorithm>
#include <cmath>

namespace app {

crowdgpu::FrameView frameView(const Camera& camera, VkExtent2D extent, double time) {
    const float eye[3] = {camera.eye.x, camera.eye.y, camera.eye.z};
    const float target[3] = {camera.target.x, camera.target.y, camera.target.z};
    return crowdgpu::lookAt(eye, target, camera.verticalFov, camera.nearPlane, camera.farPlane, extent, time);
}

CrowdShape crowdShape(const crowdgpu::Crowd& crowd) {
    CrowdShape shape;
    float center[3];
    crowd.bounds(center, shape.radius, shape.characterHeight);
    shape.center = glm::vec3(center[0], center[1], center[2]);
    return shape;
}

Camera frameCrowd(const CrowdShape& crowd, float aspect) {
    Camera camera;
    const float h = crowd.characterHeight;
    const float r = std::max(crowd.radius, h);
    // A three-quarter view from above (about 30 degrees down), so characters show their profile,
    // from just far enough that the crowd's square fills most of the narrower side of the image.
    const float halfFov = 0.5f * camera.verticalFov * std::min(1.0f, aspect);
    const float distance = r / std::tan(halfFov) * 0.72f + 1.5f * h;
    const glm::vec3 direction = glm::normalize(glm::vec3(0.55f, 0.6f, 1.0f));
    camera.target = crowd.center + glm::vec3(0.0f, 0.45f * h, 0.0f);
    camera.eye = camera.target + direction * distance;
    camera.nearPlane = std::max(0.05f, distance * 0.01f);
    camera.farPlane = distance * 4.0f + r * 4.0f;
    return camera;
}

}  // namespace app
