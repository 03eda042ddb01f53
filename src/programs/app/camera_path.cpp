#include "app/camera_path.h"

#include <algorithm>
#include <cmath>

namespace app {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kPeriod = 40.0f;  // seconds for a whole path (there and back)

// Seconds into the current period: taken in double, so the camera moves as smoothly at 1e9 s as at 0 s.
float withinPeriod(double seconds) { return static_cast<float>(seconds - std::floor(seconds / kPeriod) * kPeriod); }

// 0 -> 1 -> 0 over a period, eased at both ends so the camera never jerks.
float pingPong(float seconds) {
    const float u = seconds / kPeriod - std::floor(seconds / kPeriod);
    const float t = u < 0.5f ? 2.0f * u : 2.0f - 2.0f * u;
    return t * t * (3.0f - 2.0f * t);
}

Camera flyOver(const CrowdShape& crowd, float seconds) {
    Camera camera;
    const float h = crowd.characterHeight;
    // A circle over the crowd, looking ahead along the flight and down: near characters pass below,
    // far ones stay in view, and the ones behind are culled.
    const float angle = 2.0f * kPi * seconds / kPeriod;
    const float r = 0.55f * crowd.radius;
    const glm::vec3 ground = crowd.center + glm::vec3(r * std::cos(angle), 0.0f, r * std::sin(angle));
    const glm::vec3 forward(-std::sin(angle), 0.0f, std::cos(angle));
    camera.eye = ground + glm::vec3(0.0f, 5.0f * h, 0.0f);
    camera.target = camera.eye + forward * (12.0f * h) - glm::vec3(0.0f, 4.5f * h, 0.0f);
    camera.nearPlane = 0.05f * h;
    camera.farPlane = 2.5f * crowd.radius + 20.0f * h;
    return camera;
}

Camera descend(const CrowdShape& crowd, float seconds) {
    Camera camera;
    const float h = crowd.characterHeight;
    const float t = pingPong(seconds);
    // High: over the crowd's near edge, looking at its centre. Low: at eye level a quarter of the way
    // in, looking across the crowd.
    const glm::vec3 highEye = crowd.center + glm::vec3(0.2f, 1.1f, 0.9f) * crowd.radius;
    const glm::vec3 lowEye = crowd.center + glm::vec3(0.05f * crowd.radius, 0.95f * h, 0.25f * crowd.radius);
    const glm::vec3 highTarget = crowd.center;
    const glm::vec3 lowTarget = crowd.center + glm::vec3(0.0f, 0.8f * h, -0.5f * crowd.radius);
    camera.eye = glm::mix(highEye, lowEye, t);
    camera.target = glm::mix(highTarget, lowTarget, t);
    camera.nearPlane = 0.05f * h;
    camera.farPlane = 3.0f * crowd.radius + 20.0f * h;
    return camera;
}

}  // namespace

const char* cameraPathName(CameraPath path) {
    switch (path) {
        case CameraPath::Framed: return "framed";
        case CameraPath::Orbit: return "orbit";
        case CameraPath::FlyOver: return "fly-over";
        case CameraPath::Descend: return "descend";
    }
    return "?";
}

Camera cameraOnPath(CameraPath path, const CrowdShape& crowd, float aspect, double sceneSeconds) {
    const float seconds = withinPeriod(sceneSeconds);
    switch (path) {
        case CameraPath::Framed: return frameCrowd(crowd, aspect);
        case CameraPath::Orbit: {
            Camera camera = frameCrowd(crowd, aspect);
            const float angle = 2.0f * kPi * seconds / kPeriod;
            const glm::vec3 offset = camera.eye - camera.target;
            const float c = std::cos(angle), s = std::sin(angle);
            camera.eye = camera.target + glm::vec3(c * offset.x + s * offset.z, offset.y, c * offset.z - s * offset.x);
            return camera;
        }
        case CameraPath::FlyOver: return flyOver(crowd, seconds);
        case CameraPath::Descend: return descend(crowd, seconds);
    }
    return Camera{};
}

}  // namespace app
