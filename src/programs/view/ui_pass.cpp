#include "view/ui_pass.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include "app/host_device.h"
#include "app/error.h"
#include "view/swapchain.h"

namespace view {
namespace {

void checkImGuiVulkan(VkResult result) {
    app::check(result, "the ImGui Vulkan backend");
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// ImGui's colours are sRGB values meant for a UNORM target. The swapchain is sRGB, so the hardware
// encodes whatever the shader writes; decoding the style's colours once makes that encode give them
// back, instead of a washed-out panel.
void linearizeStyle(ImGuiStyle& style) {
    for (ImVec4& c : style.Colors) c = ImVec4(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z), c.w);
}

}  // namespace

UiPass::UiPass(const app::HostDevice& context, GLFWwindow* window, const Swapchain& swapchain) : context_(context) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    try {
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory: runs stay reproducible
        ImGui::StyleColorsDark();
        linearizeStyle(ImGui::GetStyle());
        // Chains to the key and scroll callbacks the Window installed before.
        glfwBackend_ = ImGui_ImplGlfw_InitForVulkan(window, true);

        // The backend needs one combined image sampler: the font atlas.
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
        VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
        poolInfo.maxSets = 1;
        poolInfo.poolSizeCount = 1;
        poolInfo.pPoolSizes = &size;
        CHECK_VK(vkCreateDescriptorPool(context.device, &poolInfo, nullptr, &descriptorPool_));
        createRenderPass(swapchain.format());
        createFramebuffers(swapchain);

        ImGui_ImplVulkan_InitInfo info{};
        info.Instance = context.instance;
        info.PhysicalDevice = context.physicalDevice;
        info.Device = context.device;
        info.QueueFamily = context.queueFamily;
        info.Queue = context.queue;
        info.DescriptorPool = descriptorPool_;
        info.Subpass = 0;
        info.MinImageCount = std::max(2u, swapchain.minImageCount());
        // The backend keeps this many vertex/index buffers and uses them in turn, one per frame; the
        // renderer has at most two frames in flight, so any count of at least two is never overwritten
        // while the GPU reads it.
        info.ImageCount = std::max(info.MinImageCount, swapchain.imageCount());
        info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
        info.CheckVkResultFn = checkImGuiVulkan;
        vulkanBackend_ = ImGui_ImplVulkan_Init(&info, renderPass_);
        if (!vulkanBackend_) throw app::Error("the ImGui Vulkan backend failed to initialize");
        context.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
        ImGui_ImplVulkan_DestroyFontUploadObjects();
    } catch (...) {
        release();
        throw;
    }
}

UiPass::~UiPass() { release(); }

void UiPass::release() {
    vkDeviceWaitIdle(context_.device);
    if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
    if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
    vulkanBackend_ = glfwBackend_ = false;
    destroyFramebuffers();
    if (renderPass_) vkDestroyRenderPass(context_.device, renderPass_, nullptr);
    if (descriptorPool_) vkDestroyDescriptorPool(context_.device, descriptorPool_, nullptr);
    renderPass_ = VK_NULL_HANDLE;
    descriptorPool_ = VK_NULL_HANDLE;
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
}

void UiPass::createRenderPass(VkFormat format) {
    VkAttachmentDescription attachment{};
    attachment.format = format;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the scene is already there
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    // Layouts and ordering around the pass are the barriers of present_commands, so the pass itself
    // neither transitions nor declares external dependencies.
    attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachment.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &attachment;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    CHECK_VK(vkCreateRenderPass(context_.device, &info, nullptr, &renderPass_));
}

void UiPass::createFramebuffers(const Swapchain& swapchain) {
    for (VkImageView view : swapchain.views()) {
        VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        info.renderPass = renderPass_;
        info.attachmentCount = 1;
        info.pAttachments = &view;
        info.width = swapchain.extent().width;
        info.height = swapchain.extent().height;
        info.layers = 1;
        CHECK_VK(vkCreateFramebuffer(context_.device, &info, nullptr, &framebuffers_.emplace_back()));
    }
}

void UiPass::destroyFramebuffers() {
    for (VkFramebuffer framebuffer : framebuffers_) vkDestroyFramebuffer(context_.device, framebuffer, nullptr);
    framebuffers_.clear();
}

void UiPass::onSwapchainRecreated(const Swapchain& swapchain) {
    destroyFramebuffers();
    createFramebuffers(swapchain);
}

void UiPass::beginFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void UiPass::endFrame() { ImGui::Render(); }

void UiPass::record(VkCommandBuffer cmd, std::uint32_t imageIndex, VkExtent2D extent) {
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = renderPass_;
    begin.framebuffer = framebuffers_.at(imageIndex);
    begin.renderArea = {{0, 0}, extent};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // ImGui sizes its viewport by the window, which may be larger than the swapchain's images (they
    // stop at the surface's largest extent): the panel is drawn over the part the images cover.
    ImDrawData* drawData = ImGui::GetDrawData();
    const ImVec2 scale = drawData->FramebufferScale;
    if (scale.x > 0.0f && scale.y > 0.0f)
        drawData->DisplaySize = ImVec2(std::min(drawData->DisplaySize.x, static_cast<float>(extent.width) / scale.x),
                                       std::min(drawData->DisplaySize.y, static_cast<float>(extent.height) / scale.y));
    ImGui_ImplVulkan_RenderDrawData(drawData, cmd);
    vkCmdEndRenderPass(cmd);
}

bool UiPass::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

bool UiPass::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace view
