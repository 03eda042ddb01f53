#pragma once
// The Vulkan instance, the chosen physical device, its logical device, one queue and a command pool.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace gpu {

struct ContextOptions {
    // Khronos validation with synchronization validation; every message is counted and printed.
    bool validation = false;
    // "" picks the best device; a number picks by index; anything else by name substring.
    std::string deviceSelector;
    // Instance extensions a window system needs (from GLFW); empty when headless.
    std::vector<std::string> instanceExtensions;
    // Ask for VK_KHR_swapchain (the viewer).
    bool swapchain = false;
};

struct DeviceDescription {
    std::uint32_t index;
    std::string name;
    std::string type;    // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;  // driver name and info, e.g. "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::uint32_t apiVersion;
};

class SetupQueue;

// A device somebody else created (the host of the library): the context only looks at it. Its setup
// commands wait in a SetupQueue for the host to record; it has no queue or command pool of its own.
struct BorrowedHandles {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    bool fragmentStoresAndAtomics = false;  // whether the host enabled it (two-pass-direct needs it)
};

// Every physical device the loader reports. Throws Error when there is no Vulkan at all.
std::vector<DeviceDescription> listDevices();

class VulkanContext {
public:
    explicit VulkanContext(const ContextOptions& options);
    // Wraps a borrowed device; destroys nothing of it.
    explicit VulkanContext(const BorrowedHandles& borrowed);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    DeviceDescription description{};
    bool multiDrawIndirect = false;
    bool fragmentStores = false;

    // Validation messages (warnings and errors) seen since creation.
    std::uint64_t validationMessages() const { return validationMessageCount_.load(); }
    // Device-local memory heap size in bytes (the largest such heap).
    std::uint64_t deviceLocalBytes() const;
    // Nanoseconds per timestamp tick, or 0 when the queue has no timestamps.
    double timestampPeriodNs() const { return timestampPeriodNs_; }
    void setDebugName(VkObjectType type, std::uint64_t handle, const char* name) const;
    // Where setup commands wait on a borrowed device; null when the context owns its device and
    // submits them itself.
    SetupQueue* deferredSetup() const { return setup_.get(); }
    bool borrowed() const { return setup_ != nullptr; }

private:
    void createInstance(const ContextOptions& options);
    void pickPhysicalDevice(const std::string& selector);
    void createDevice(const ContextOptions& options);
    void release();

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::atomic<std::uint64_t> validationMessageCount_{0};
    double timestampPeriodNs_ = 0.0;
    bool debugUtils_ = false;
    std::unique_ptr<SetupQueue> setup_;

    friend VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT*, void*);
};

}  // namespace gpu
