#pragma once
// The device the library works on: always somebody else's (the host's), looked at, never destroyed.
// Its properties, limits and the timestamp period are read once here.
#include <cstdint>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

namespace gpu {

struct DeviceDescription {
    std::uint32_t index;
    std::string name;
    std::string type;    // "discrete", "integrated", "virtual", "cpu", "other"
    std::string driver;  // driver name and info, e.g. "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::uint32_t apiVersion;
};

class SetupQueue;

// The host's handles. Without a queue (crowdgpu::Renderer) setup commands wait in a SetupQueue for
// the host to record. With one (the library's own tests, which check each pass alone) the context
// makes a command pool of its own and submits setup at once, waiting for it.
struct BorrowedHandles {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    bool fragmentStoresAndAtomics = false;  // whether the host enabled it (two-pass-direct needs it)
    VkQueue queue = VK_NULL_HANDLE;
    bool debugNames = false;  // the instance has VK_EXT_debug_utils: name objects for validation messages
    // shaderInt64 and shaderBufferInt64Atomics, whether the host enabled both (the compute rasterizer's
    // visibility buffer needs them).
    bool int64Atomics = false;
};

class VulkanContext {
public:
    explicit VulkanContext(const BorrowedHandles& borrowed);
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;           // null: setup is deferred to the host
    std::uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;  // the context's own, with a queue only
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    DeviceDescription description{};
    bool multiDrawIndirect = true;
    bool fragmentStores = false;
    bool int64Atomics = false;  // BorrowedHandles::int64Atomics

    // Device-local memory heap size in bytes (the largest such heap).
    std::uint64_t deviceLocalBytes() const;
    // Nanoseconds per timestamp tick, or 0 when the queue has no timestamps.
    double timestampPeriodNs() const { return timestampPeriodNs_; }
    void setDebugName(VkObjectType type, std::uint64_t handle, const char* name) const;
    // Where setup commands wait for the host; null when the context has a queue and submits them.
    SetupQueue* deferredSetup() const { return setup_.get(); }

private:
    double timestampPeriodNs_ = 0.0;
    bool debugNames_ = false;
    std::unique_ptr<SetupQueue> setup_;
};

}  // namespace gpu
