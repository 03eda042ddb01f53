#include "view/window.h"

#include <algorithm>
#include <utility>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "app/error.h"

namespace view {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

}  // namespace

Window::Window(VkExtent2D size, const std::string& title) {
    if (!glfwInit())
        throw app::Error("cannot open a window (" + lastGlfwError() +
                         "); crowd-view needs a display: run it under X11/Wayland or xvfb-run, or use crowd-render");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw app::Error("GLFW found no Vulkan loader; install libvulkan1 and a Vulkan driver");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws; no OpenGL context
    window_ = glfwCreateWindow(static_cast<int>(size.width), static_cast<int>(size.height), title.c_str(), nullptr,
                               nullptr);
    if (!window_) {
        const std::string error = lastGlfwError();
        glfwTerminate();
        throw app::Error("cannot create a " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                         " window: " + error);
    }
    glfwSetWindowUserPointer(window_, this);
    // Installed before ImGui's backend, which chains to these (see UiPass).
    glfwSetKeyCallback(window_, onKey);
    glfwSetScrollCallback(window_, onScroll);
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw app::Error("GLFW cannot present with Vulkan here (" + lastGlfwError() + ")");
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    CHECK_VK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {static_cast<std::uint32_t>(std::max(width, 0)), static_cast<std::uint32_t>(std::max(height, 0))};
}

void Window::pollEvents() { glfwPollEvents(); }

bool Window::minimized() const {
    const VkExtent2D size = framebufferSize();
    return size.width == 0 || size.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
}

bool Window::waitWhileMinimized() {
    while (minimized() && !shouldClose()) glfwWaitEvents();
    return !shouldClose();
}

void Window::limitFramebufferSize(VkExtent2D largest) {
    // GLFW sizes windows in screen units; the framebuffer may have more pixels per unit (high DPI).
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    const VkExtent2D pixels = framebufferSize();
    if (width <= 0 || height <= 0 || pixels.width == 0 || pixels.height == 0) return;  // minimized: sizes unknown
    const auto units = [](std::uint32_t limit, std::uint32_t pixels, int units) {
        return std::max(1, static_cast<int>(static_cast<std::uint64_t>(limit) * static_cast<std::uint64_t>(units) / pixels));
    };
    const int maxWidth = units(largest.width, pixels.width, width);
    const int maxHeight = units(largest.height, pixels.height, height);
    glfwSetWindowSizeLimits(window_, GLFW_DONT_CARE, GLFW_DONT_CARE, maxWidth, maxHeight);
    if (width > maxWidth || height > maxHeight) glfwSetWindowSize(window_, std::min(width, maxWidth), std::min(height, maxHeight));
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

std::vector<int> Window::takeKeyPresses() { return std::exchange(keyPresses_, {}); }

float Window::takeWheel() { return std::exchange(wheel_, 0.0f); }

void Window::onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_PRESS) static_cast<Window*>(glfwGetWindowUserPointer(window))->keyPresses_.push_back(key);
}

void Window::onScroll(GLFWwindow* window, double, double y) {
    static_cast<Window*>(glfwGetWindowUserPointer(window))->wheel_ += static_cast<float>(y);
}

}  // namespace view
