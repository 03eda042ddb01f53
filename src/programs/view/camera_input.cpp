#include "view/camera_input.h"

#include <GLFW/glfw3.h>

namespace view {
namespace {

float axis(GLFWwindow* window, int positive, int negative) {
    return static_cast<float>(glfwGetKey(window, positive) == GLFW_PRESS) -
           static_cast<float>(glfwGetKey(window, negative) == GLFW_PRESS);
}

}  // namespace

CameraInput CameraInputReader::read(GLFWwindow* window, float wheel, bool mouseFree, bool keysFree, float seconds) {
    glm::dvec2 cursor;
    glfwGetCursorPos(window, &cursor.x, &cursor.y);
    const glm::vec2 moved = hasCursor_ ? glm::vec2(cursor - lastCursor_) : glm::vec2(0.0f);
    lastCursor_ = cursor;
    hasCursor_ = true;

    CameraInput input;
    input.seconds = seconds;
    if (mouseFree) {
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) input.orbitDrag = moved;
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS) input.lookDrag = moved;
        input.wheel = wheel;
    }
    if (keysFree) {
        input.move = {axis(window, GLFW_KEY_D, GLFW_KEY_A), axis(window, GLFW_KEY_E, GLFW_KEY_Q),
                      axis(window, GLFW_KEY_W, GLFW_KEY_S)};
        input.fast = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    }
    return input;
}

}  // namespace view
