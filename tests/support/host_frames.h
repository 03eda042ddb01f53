#pragma once
// A host of the public API, as a game drives it: the test context's device lent to crowdgpu::Renderer,
// frames in flight each with its command buffer and fence, the host's own colour pass into a target, and
// frames it may record and then drop (never submit), as an engine does when its swapchain goes out of
// date.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "app/render_target.h"
#include "crowdgpu/renderer.hpp"
#include "gpu/vulkan_context.h"

namespace test {

// The host's device as the library sees it: the test context's handles and the features it enabled.
struct LentDevice {
    VkPhysicalDeviceVulkan11Features vulkan11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    crowdgpu::Device device;
    explicit LentDevice(const gpu::VulkanContext& context);
    LentDevice(const LentDevice&) = delete;
    LentDevice& operator=(const LentDevice&) = delete;
};

class HostFrames {
public:
    HostFrames(const gpu::VulkanContext& context, const app::HostDevice& device, VkExtent2D size,
               const crowdgpu::TargetFormat& format, std::uint32_t framesInFlight = 2);
    ~HostFrames();
    HostFrames(const HostFrames&) = delete;
    HostFrames& operator=(const HostFrames&) = delete;

    // The renderer's setup, submitted and waited for.
    void setup(crowdgpu::Renderer& renderer);
    // One frame of `renderer` drawing `crowd` (advanced to view.time by the caller), in the next slot:
    // compute, shadows, the host's pass with the characters (ground and sky on: RendererSettings). With
    // `drop`, the frame is recorded and its command buffer reset, never submitted. `before`, when given,
    // records the host's own work first (its pass that writes device samples).
    void frame(crowdgpu::Renderer& renderer, const crowdgpu::Crowd& crowd, const crowdgpu::FrameView& view,
               bool drop = false, const crowdgpu::DeviceSamples* samples = nullptr,
               const std::function<void(VkCommandBuffer)>& before = {});
    // Waits for every frame in flight and reads the last submitted frame's picture.
    app::Rgba8Image finish();
    // The slot the last frame took.
    std::uint32_t lastSlot() const { return (next_ + framesInFlight_ - 1) % framesInFlight_; }
    void waitIdle();

private:
    const gpu::VulkanContext& context_;
    app::RenderTarget target_;
    std::uint32_t framesInFlight_;
    std::vector<VkCommandBuffer> commands_;
    std::vector<VkFence> fences_;
    std::uint32_t next_ = 0;
};

}  // namespace test
