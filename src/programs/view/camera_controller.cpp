#include "view/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace view {
namespace {

constexpr float kRadiansPerPixel = 0.005f;
// About 83 degrees: glm::lookAt's up vector (+y) must never be parallel to the view direction.
constexpr float kMaxElevation = 1.45f;
constexpr float kZoomPerWheelStep = 0.85f;
constexpr float kFlySpeedPerWheelStep = 1.25f;
constexpr float kFollowDistanceInHeights = 3.0f;

// A direction as turn about +y (azimuth, 0 along +z), tilt above the horizon (elevation) and length.
struct Spherical {
    float azimuth;
    float elevation;
    float length;
};

Spherical toSpherical(const glm::vec3& v) {
    const float length = glm::length(v);
    return {std::atan2(v.x, v.z), std::asin(std::clamp(v.y / length, -1.0f, 1.0f)), length};
}

glm::vec3 fromSpherical(const Spherical& s) {
    const float horizontal = std::cos(s.elevation) * s.length;
    return {std::sin(s.azimuth) * horizontal, std::sin(s.elevation) * s.length, std::cos(s.azimuth) * horizontal};
}

Spherical turned(const glm::vec3& v, float azimuthDelta, float elevationDelta) {
    Spherical s = toSpherical(v);
    s.azimuth += azimuthDelta;
    s.elevation = std::clamp(s.elevation + elevationDelta, -kMaxElevation, kMaxElevation);
    return s;
}

}  // namespace

const char* cameraModeName(CameraMode mode) { return mode == CameraMode::Orbit ? "orbit" : "fly"; }

void CameraController::setHome(const app::Camera& home, const SceneScale& scale) {
    home_ = home;
    scale_ = scale;
}

void CameraController::centerOn(const glm::vec3& point) {
    glm::vec3 direction = camera_.eye - camera_.target;
    if (glm::length(direction) <= 0.0f) direction = home_.eye - home_.target;
    const float distance = kFollowDistanceInHeights * scale_.characterHeight;
    camera_.target = point;
    camera_.eye = point + glm::normalize(direction) * distance;
    mode_ = CameraMode::Orbit;
    fitClipPlanes();
}

void CameraController::track(const glm::vec3& point) {
    const glm::vec3 delta = point - camera_.target;
    if (delta == glm::vec3(0.0f)) return;
    camera_.eye += delta;
    camera_.target += delta;
    fitClipPlanes();
}

void CameraController::update(const CameraInput& input) {
    bool moved = false;
    if (mode_ == CameraMode::Orbit) {
        if (input.orbitDrag != glm::vec2(0.0f)) orbit(input.orbitDrag), moved = true;
        if (input.wheel != 0.0f) zoom(input.wheel), moved = true;
    } else {
        if (input.lookDrag != glm::vec2(0.0f)) look(input.lookDrag), moved = true;
        if (input.wheel != 0.0f)
            flySpeedScale_ =
                std::clamp(flySpeedScale_ * std::pow(kFlySpeedPerWheelStep, input.wheel), 1.0f / 64.0f, 64.0f);
        if (input.move != glm::vec3(0.0f) && input.seconds > 0.0f)
            fly(input.move, input.fast, input.seconds), moved = true;
    }
    if (moved) fitClipPlanes();
}

void CameraController::orbit(glm::vec2 drag) {
    // "Grab the world": dragging down lifts the camera to look from higher up.
    const Spherical s = turned(camera_.eye - camera_.target, -drag.x * kRadiansPerPixel, drag.y * kRadiansPerPixel);
    camera_.eye = camera_.target + fromSpherical(s);
}

void CameraController::zoom(float wheel) {
    const glm::vec3 offset = camera_.eye - camera_.target;
    const float distance = glm::length(offset);
    // Close enough to see one character's face, far enough to see the whole crowd as a speck.
    const float nearest = std::min(0.5f * scale_.characterHeight, distance);
    const float farthest = std::max(20.0f * homeDistance(), distance);
    const float wanted = std::clamp(distance * std::pow(kZoomPerWheelStep, wheel), nearest, farthest);
    camera_.eye = camera_.target + offset * (wanted / distance);
}

void CameraController::look(glm::vec2 drag) {
    const glm::vec3 forward = camera_.target - camera_.eye;
    const Spherical s = turned(forward, -drag.x * kRadiansPerPixel, -drag.y * kRadiansPerPixel);
    camera_.target = camera_.eye + fromSpherical(s);
}

void CameraController::fly(const glm::vec3& move, bool fast, float seconds) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 forward = glm::normalize(camera_.target - camera_.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    // A few character heights per second near a small crowd; a quarter of the crowd per second above a big one.
    const float speed =
        std::max(2.0f * scale_.characterHeight, 0.25f * scale_.radius) * flySpeedScale_ * (fast ? 4.0f : 1.0f);
    const glm::vec3 delta = (right * move.x + up * move.y + forward * move.z) * speed * seconds;
    camera_.eye += delta;
    camera_.target += delta;
}

void CameraController::fitClipPlanes() {
    // The near plane follows the camera in for close-ups (depth precision is spent where one looks);
    // the far plane grows so the whole crowd stays in view from wherever the camera went.
    const float distance = glm::length(camera_.eye - camera_.target);
    camera_.nearPlane = std::clamp(0.01f * distance, 0.001f * homeDistance(), home_.nearPlane);
    camera_.farPlane = std::max(home_.farPlane, 2.0f * glm::length(camera_.eye - scale_.center) + 4.0f * scale_.radius);
}

}  // namespace view
