#pragma once
// Turns the window's mouse and keyboard state into one frame of camera input.
#include <glm/glm.hpp>

#include "view/camera_controller.h"

struct GLFWwindow;

namespace view {

class CameraInputReader {
public:
    // `wheel`: steps since the last frame. The mouse and keys count only where the UI panel does
    // not want them (dragging a slider must not orbit the camera).
    CameraInput read(GLFWwindow* window, float wheel, bool mouseFree, bool keysFree, float seconds);

private:
    glm::dvec2 lastCursor_{0.0};
    bool hasCursor_ = false;
};

}  // namespace view
