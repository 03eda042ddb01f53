#pragma once
// Dear ImGui on the swapchain: the GLFW and Vulkan backends (compiled into Debian's libimgui.a),
// a one-subpass render pass that loads the blitted scene and blends the panel onto it, and one
// framebuffer per swapchain image. ImGui 1.86's Vulkan backend builds its pipeline against a
// VkRenderPass, hence a render pass here while the scene uses dynamic rendering.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace app { class HostDevice; }

namespace view {

class Swapchain;

class UiPass {
public:
    UiPass(const app::HostDevice& context, GLFWwindow* window, const Swapchain& swapchain);
    ~UiPass();
    UiPass(const UiPass&) = delete;
    UiPass& operator=(const UiPass&) = delete;

    // New framebuffers for the swapchain's new images (the device is idle after a recreate).
    void onSwapchainRecreated(const Swapchain& swapchain);

    // ImGui widgets may be declared between beginFrame and endFrame; record draws what they made.
    void beginFrame();
    void endFrame();
    // Draws the frame's UI onto swapchain image `imageIndex` (COLOR_ATTACHMENT_OPTIMAL, stays so).
    void record(VkCommandBuffer cmd, std::uint32_t imageIndex, VkExtent2D extent);

    // Whether the panel has the mouse or keyboard (the camera and shortcuts then leave them alone).
    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    void createRenderPass(VkFormat format);
    void createFramebuffers(const Swapchain& swapchain);
    void destroyFramebuffers();
    void release();

    const app::HostDevice& context_;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> framebuffers_;
    bool glfwBackend_ = false;
    bool vulkanBackend_ = false;
};

}  // namespace view
