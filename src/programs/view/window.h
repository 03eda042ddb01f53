#pragma once
// The GLFW window: creation without an OpenGL context, its framebuffer size, the wait while it is
// minimized, and the input that arrives as events (key presses, wheel) rather than as state.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace view {

class Window {
public:
    // Initializes GLFW and opens a window of `size` screen units. Throws app::Error when there is no
    // display or no Vulkan support in GLFW.
    Window(VkExtent2D size, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // The instance extensions a surface for this window needs.
    static std::vector<std::string> requiredInstanceExtensions();
    // The caller owns the surface and destroys it before the instance.
    VkSurfaceKHR createSurface(VkInstance instance) const;

    // Framebuffer pixels (may differ from screen units on high-DPI displays); 0x0 while minimized.
    VkExtent2D framebufferSize() const;
    void pollEvents();
    // Minimized: a zero-sized framebuffer (Windows, some Wayland compositors), or iconified (X11
    // keeps the size, but nothing drawn would be seen).
    bool minimized() const;
    // Blocks, without spinning, while minimized: a swapchain cannot have a zero extent, and drawing
    // unseen frames only heats the GPU. Returns false when the window was closed meanwhile.
    bool waitWhileMinimized();
    // Keeps the framebuffer within `largest` pixels: size limits for the window manager, and a resize
    // now if the window is already larger (other clients, or a missing window manager, can still make it
    // larger; call again then).
    void limitFramebufferSize(VkExtent2D largest);
    bool shouldClose() const;
    void requestClose();

    // Keys pressed (GLFW key codes) and wheel steps since the last call. Taken from callbacks, because
    // a tap shorter than a frame never shows in the key state that a slow frame polls.
    std::vector<int> takeKeyPresses();
    float takeWheel();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double x, double y);

    GLFWwindow* window_ = nullptr;
    std::vector<int> keyPresses_;
    float wheel_ = 0.0f;
};

}  // namespace view
