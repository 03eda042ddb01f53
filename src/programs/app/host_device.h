#pragma once
// The programs' Vulkan device, made the way a host of the library makes one: an instance (with the
// Khronos validation layer and synchronization validation when asked), the best Vulkan 1.3 device or
// the one named, a logical device with the features crowdgpu::enableRequiredFeatures asks for, one
// graphics+compute queue and a command pool. The renderer borrows it through libraryDevice().
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <crowdgpu/renderer.hpp>

namespace app {

struct HostDeviceOptions {
    // Khronos validation with synchronization validation; every message is counted and printed.
    bool validation = false;
    // "" picks the best device; a number picks by index; anything else by name substring.
    std::string deviceSelector;
    // Instance extensions a window system needs (from GLFW); empty when headless.
    std::vector<std::string> instanceExtensions;
    bool swapchain = false;  // ask for VK_KHR_swapchain (the viewer)
};

struct DeviceDescription {
    std::uint32_t index;
    std::string name;
    std::string type;    // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;  // driver name and info, e.g. "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::uint32_t apiVersion;
};

// Every physical device the loader reports. Throws Error when there is no Vulkan at all.
std::vector<DeviceDescription> listDevices();

class HostDevice {
public:
    explicit HostDevice(const HostDeviceOptions& options);
    ~HostDevice();
    HostDevice(const HostDevice&) = delete;
    HostDevice& operator=(const HostDevice&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    DeviceDescription description{};
    bool validation = false;

    // What the library borrows: the handles and the feature chain the device was made with.
    crowdgpu::Device libraryDevice() const;
    // Validation messages (warnings and errors) seen since creation.
    std::uint64_t validationMessages() const { return validationMessages_.load(); }
    // The largest device-local heap, in bytes.
    std::uint64_t deviceLocalBytes() const;
    // Nanoseconds per timestamp tick, or 0 when the queue has no timestamps.
    double timestampPeriodNs() const { return timestampPeriodNs_; }
    // A memory type allowed by `typeBits` with `flags`, or -1.
    int memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const;
    // Records `record` into a fresh command buffer, submits it and waits for it (setup and readback).
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

    // Whether the device was created with shaderInt64 and shaderBufferInt64Atomics (the compute rasterizer).
    bool int64Atomics() const {
        return enabled_.features.features.shaderInt64 == VK_TRUE && enabled_.vulkan12.shaderBufferInt64Atomics == VK_TRUE;
    }

private:
    void createInstance(const HostDeviceOptions& options);
    void pickPhysicalDevice(const std::string& selector);
    void createDevice(const HostDeviceOptions& options);
    void release();

    struct FeatureChain {
        VkPhysicalDeviceVulkan11Features vulkan11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
        VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    } enabled_;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<std::uint64_t> validationMessages_{0};
    double timestampPeriodNs_ = 0.0;

    friend VkBool32 VKAPI_CALL countValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                      VkDebugUtilsMessageTypeFlagsEXT,
                                                      const VkDebugUtilsMessengerCallbackDataEXT*, void*);
};

}  // namespace app
