#include "support/host_frames.h"

#include <stdexcept>

#include "gpu/one_shot_commands.h"

namespace test {

namespace {

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed");
}

}  // namespace

LentDevice::LentDevice(const gpu::VulkanContext& context) {
    vulkan12.pNext = &vulkan11;
    vulkan13.pNext = &vulkan12;
    features.pNext = &vulkan13;
    crowdgpu::enableRequiredFeatures(features, vulkan11, vulkan12, vulkan13);
    features.features.fragmentStoresAndAtomics = context.fragmentStores;  // two-pass-direct's, when there
    // The compute rasterizer's 64-bit atomics, optional features a host enables when it wants them.
    features.features.shaderInt64 = vulkan12.shaderBufferInt64Atomics = context.int64Atomics;
    device = {context.instance, context.physicalDevice, context.device, context.queueFamily, &features};
}

HostFrames::HostFrames(const gpu::VulkanContext& context, const app::HostDevice& device, VkExtent2D size,
                       const crowdgpu::TargetFormat& format, std::uint32_t framesInFlight)
    : context_(context), target_(device, size, format), framesInFlight_(framesInFlight) {
    commands_.resize(framesInFlight);
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context.commandPool;
    allocate.commandBufferCount = framesInFlight;
    check(vkAllocateCommandBuffers(context.device, &allocate, commands_.data()), "vkAllocateCommandBuffers");
    for (std::uint32_t i = 0; i < framesInFlight; ++i) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        VkFence fence = VK_NULL_HANDLE;
        check(vkCreateFence(context.device, &info, nullptr, &fence), "vkCreateFence");
        fences_.push_back(fence);
    }
}

HostFrames::~HostFrames() {
    waitIdle();
    for (VkFence fence : fences_) vkDestroyFence(context_.device, fence, nullptr);
    vkFreeCommandBuffers(context_.device, context_.commandPool, framesInFlight_, commands_.data());
}

void HostFrames::waitIdle() {
    vkWaitForFences(context_.device, framesInFlight_, fences_.data(), VK_TRUE, UINT64_MAX);
}

void HostFrames::setup(crowdgpu::Renderer& renderer) {
    gpu::runOneShotNow(context_, [&](VkCommandBuffer cmd) { renderer.recordSetup(cmd); });
    renderer.setupCompleted();
}

void HostFrames::frame(crowdgpu::Renderer& renderer, const crowdgpu::Crowd& crowd, const crowdgpu::FrameView& view,
                       bool drop, const crowdgpu::DeviceSamples* samples,
                       const std::function<void(VkCommandBuffer)>& before) {
    const std::uint32_t slot = next_;
    next_ = (next_ + 1) % framesInFlight_;
    check(vkWaitForFences(context_.device, 1, &fences_[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences");
    VkCommandBuffer cmd = commands_[slot];
    check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
    if (before) before(cmd);
    if (samples)
        renderer.recordCompute(cmd, slot, view, crowd, *samples);
    else
        renderer.recordCompute(cmd, slot, view, crowd);
    renderer.recordShadows(cmd, slot);
    const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
    target_.beginRendering(cmd, sky);
    renderer.recordCharacters(cmd, slot);
    target_.endRendering(cmd);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    if (drop) return;  // recorded, never submitted: its fence stays signalled
    check(vkResetFences(context_.device, 1, &fences_[slot]), "vkResetFences");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(context_.queue, 1, &submit, fences_[slot]), "vkQueueSubmit");
}

app::Rgba8Image HostFrames::finish() {
    waitIdle();
    return target_.readback();
}

}  // namespace test
