#pragma once
// The viewer's camera control: orbit around a point (left drag, wheel zoom) or fly (WASD, right-drag
// look), reset to a home view, and centring on a followed character. It works on per-frame input
// deltas and knows nothing of the window system, so it is tested on its own.
#include <glm/glm.hpp>

#include "app/camera.h"

namespace view {

enum class CameraMode { Orbit, Fly };
const char* cameraModeName(CameraMode mode);

// One frame of camera input, already stripped of what the UI panel took.
struct CameraInput {
    glm::vec2 orbitDrag{0.0f};  // cursor pixels moved with the left button held
    glm::vec2 lookDrag{0.0f};   // cursor pixels moved with the right button held
    float wheel = 0.0f;         // wheel steps, positive away from the user
    glm::vec3 move{0.0f};       // fly direction: x right, y up, z forward; each -1, 0 or 1
    bool fast = false;          // shift held
    float seconds = 0.0f;       // real time since the previous frame
};

// How big the scene is: scales zoom limits, fly speed, the follow distance and the clip planes.
struct SceneScale {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    float characterHeight = 1.0f;
};

class CameraController {
public:
    // The view that R returns to (reset()), and the scene's size. The current view stays: a resized
    // window gets a new home framing without the camera jumping.
    void setHome(const app::Camera& home, const SceneScale& scale);
    void reset() { camera_ = home_; }

    CameraMode mode() const { return mode_; }
    void setMode(CameraMode mode) { mode_ = mode; }

    // Orbits `point` from close by from now on (orbit mode, a few character heights away, same direction).
    void centerOn(const glm::vec3& point);
    // Moves the view with a followed point that moved (keeps the offset to it).
    void track(const glm::vec3& point);

    // Applies one frame of input. Without input the camera stays exactly as it was, so scripted
    // runs see the home view bit for bit.
    void update(const CameraInput& input);

    const app::Camera& camera() const { return camera_; }

private:
    void orbit(glm::vec2 drag);
    void zoom(float wheel);
    void look(glm::vec2 drag);
    void fly(const glm::vec3& move, bool fast, float seconds);
    void fitClipPlanes();
    float homeDistance() const { return glm::length(home_.eye - home_.target); }

    app::Camera home_;
    app::Camera camera_;
    SceneScale scale_;
    CameraMode mode_ = CameraMode::Orbit;
    float flySpeedScale_ = 1.0f;  // the wheel's doing in fly mode
};

}  // namespace view
