#include "render/frame_view.h"

#include <cmath>

namespace render {
namespace {

constexpr float kLargestFar = 1.0e6f;

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

float aspectOf(const FrameView& view) { return std::abs(view.projection[1][1] / view.projection[0][0]); }

Camera cameraOf(const FrameView& frame) {
    const glm::mat4 world = glm::inverse(frame.view);
    Camera camera;
    camera.eye = glm::vec3(world[3]);
    camera.target = camera.eye - glm::normalize(glm::vec3(world[2]));  // the view looks down its -z
    const glm::mat4& p = frame.projection;
    camera.verticalFov = 2.0f * std::atan(1.0f / std::abs(p[1][1]));
    // A right-handed, depth 0..1 perspective: z_clip = p22 z + p32, w_clip = -z.
    camera.nearPlane = p[3][2] / p[2][2];
    const float far = p[3][2] / (p[2][2] + 1.0f);
    camera.farPlane = std::isfinite(far) && far > camera.nearPlane ? std::min(far, kLargestFar) : kLargestFar;
    return camera;
}

FrameView frameViewOf(const Camera& camera, VkExtent2D extent, double time) {
    const float aspect = static_cast<float>(extent.width) / static_cast<float>(extent.height);
    return {camera.view(), camera.projection(aspect), {{0, 0}, extent}, time};
}

bool isPerspectiveView(const FrameView& frame) {
    if (!finite(frame.view) || !finite(frame.projection)) return false;
    if (std::abs(glm::determinant(frame.view)) < 1e-12f) return false;
    const glm::mat4& p = frame.projection;
    return p[0][0] != 0.0f && p[1][1] != 0.0f && p[2][3] < 0.0f && p[3][3] == 0.0f && p[2][2] != 0.0f &&
           p[3][2] / p[2][2] > 0.0f;
}

}  // namespace render
