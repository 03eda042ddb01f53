#pragma once
// The programs' camera: a perspective camera looking at a point, turned into the library's view by
// crowdgpu::lookAt. Scenes move it along camera paths (app/camera_path.h).
#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include <crowdgpu/renderer.hpp>

namespace app {

struct Camera {
    glm::vec3 eye{0.0f, 10.0f, 20.0f};
    glm::vec3 target{0.0f};
    float verticalFov = 0.7f;  // radians
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
};

// The view and projection of `camera` over an image of `extent` at animation time `time`.
crowdgpu::FrameView frameView(const Camera& camera, VkExtent2D extent, double time);

// What a camera path needs to know of the crowd: where it stands and how big its characters are.
struct CrowdShape {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float characterHeight = 1.0f;
};
CrowdShape crowdShape(const crowdgpu::Crowd& crowd);

// A camera in front of (+z) and above a crowd of this shape, framing all of it.
Camera frameCrowd(const CrowdShape& crowd, float aspect);

}  // namespace app
