#include "app/host_device.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

#include "app/error.h"

namespace app {

VkBool32 VKAPI_CALL countValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                           VkDebugUtilsMessageTypeFlagsEXT,
                                           const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    static_cast<HostDevice*>(user)->validationMessages_++;
    const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
    std::fprintf(stderr, "validation %s: %s\n", level, data->pMessage);
    return VK_FALSE;
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

// Lower is preferred: a discrete GPU over an integrated one over the rest (lavapipe last).
int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
        default: return 4;
    }
}

DeviceDescription describe(VkPhysicalDevice device, std::uint32_t index) {
    static const char* const typeNames[] = {"other", "integrated", "discrete", "virtual", "cpu"};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &properties);
    const auto type = static_cast<std::size_t>(properties.properties.deviceType);
    return {index, properties.properties.deviceName, type < 5 ? typeNames[type] : "other",
            std::string(driver.driverName) + " " + driver.driverInfo, properties.properties.apiVersion};
}

VkInstance createBareInstance(const std::vector<const char*>& layers, const std::vector<const char*>& extensions,
                              const void* next) {
    VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    application.pApplicationName = "crowd-skinning";
    application.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, next};
    info.pApplicationInfo = &application;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
        throw Error("no Vulkan driver found (vkCreateInstance: " + std::string(resultName(result)) +
                    "); install mesa-vulkan-drivers for the CPU device lavapipe, or a GPU driver");
    check(result, "vkCreateInstance");
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
    return devices;
}

// The index of the device `selector` names ("" the best Vulkan 1.3 one, a number, a name's part).
std::size_t chooseDevice(const std::vector<VkPhysicalDevice>& devices, const std::vector<DeviceDescription>& described,
                         const std::string& selector) {
    if (selector.empty()) {
        int best = -1, bestRank = 1 << 30;
        for (std::size_t i = 0; i < devices.size(); ++i) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(devices[i], &p);
            if (p.apiVersion >= VK_API_VERSION_1_3 && typeRank(p.deviceType) < bestRank)
                bestRank = typeRank(p.deviceType), best = static_cast<int>(i);
        }
        if (best < 0) throw Error("no Vulkan 1.3 device found (" + described[0].name + " is older)");
        return static_cast<std::size_t>(best);
    }
    if (std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
        const unsigned long index = std::stoul(selector);
        if (index >= devices.size())
            throw Error("--device " + selector + ": only " + std::to_string(devices.size()) +
                        " device(s); see --list-devices");
        return index;
    }
    for (const DeviceDescription& d : described)
        if (d.name.find(selector) != std::string::npos) return d.index;
    throw Error("--device " + selector + ": no device name contains it; see --list-devices");
}

}  // namespace

std::vector<DeviceDescription> listDevices() {
    VkInstance instance = createBareInstance({}, {}, nullptr);
    std::vector<DeviceDescription> result;
    std::uint32_t index = 0;
    for (VkPhysicalDevice device : physicalDevices(instance)) result.push_back(describe(device, index++));
    vkDestroyInstance(instance, nullptr);
    return result;
}

HostDevice::HostDevice(const HostDeviceOptions& options) : validation(options.validation) {
    try {
        createInstance(options);
        pickPhysicalDevice(options.deviceSelector);
        createDevice(options);
    } catch (...) {
        release();
        throw;
    }
}

HostDevice::~HostDevice() { release(); }

void HostDevice::release() {
    if (device) {
        vkDeviceWaitIdle(device);
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        vkDestroyDevice(device, nullptr);
        device = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance) vkDestroyInstance(instance, nullptr);
    instance = VK_NULL_HANDLE;
}

void HostDevice::createInstance(const HostDeviceOptions& options) {
    std::vector<const char*> layers, extensions;
    for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
    if (options.validation) {
        if (!hasLayer(kValidationLayer))
            throw Error("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                        "(apt-get install vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    // Synchronization validation is off by default in the layer; the tests rely on it.
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = countValidationMessage;
    messengerInfo.pUserData = this;
    messengerInfo.pNext = &features;  // chained so messages during vkCreateInstance itself count too
    instance = createBareInstance(layers, extensions, options.validation ? &messengerInfo : nullptr);
    if (!options.validation) return;
    messengerInfo.pNext = nullptr;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    check(create(instance, &messengerInfo, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

void HostDevice::pickPhysicalDevice(const std::string& selector) {
    const std::vector<VkPhysicalDevice> devices = physicalDevices(instance);
    if (devices.empty()) throw Error("no Vulkan device found; install mesa-vulkan-drivers for the CPU device lavapipe");
    std::vector<DeviceDescription> described;
    for (std::uint32_t i = 0; i < devices.size(); ++i) described.push_back(describe(devices[i], i));
    const std::size_t chosen = chooseDevice(devices, described, selector);
    physicalDevice = devices[chosen];
    description = described[chosen];
    if (description.apiVersion < VK_API_VERSION_1_3)
        throw Error("device " + description.name + " supports only Vulkan " +
                    std::to_string(VK_API_VERSION_MAJOR(description.apiVersion)) + "." +
                    std::to_string(VK_API_VERSION_MINOR(description.apiVersion)) + "; 1.3 is required");
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
}

void HostDevice::createDevice(const HostDeviceOptions& options) {
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    const auto family = std::find_if(families.begin(), families.end(),
                                     [&](const VkQueueFamilyProperties& f) { return (f.queueFlags & needed) == needed; });
    if (family == families.end()) throw Error("device " + description.name + " has no graphics+compute queue");
    queueFamily = static_cast<std::uint32_t>(family - families.begin());
    if (family->timestampValidBits > 0) timestampPeriodNs_ = properties.limits.timestampPeriod;

    // The library says what it needs and checks it; the device enables exactly that, plus
    // fragmentStoresAndAtomics where the device has it (the two-pass-direct method), and 64-bit
    // integers with their buffer atomics where it has both (the compute rasterizer, --raster).
    if (const std::string missing = crowdgpu::checkPhysicalDevice(physicalDevice); !missing.empty())
        throw Error(missing);
    VkPhysicalDeviceFeatures supported;
    vkGetPhysicalDeviceFeatures(physicalDevice, &supported);
    enabled_.vulkan12.pNext = &enabled_.vulkan11;
    enabled_.vulkan13.pNext = &enabled_.vulkan12;
    enabled_.features.pNext = &enabled_.vulkan13;
    crowdgpu::enableRequiredFeatures(enabled_.features, enabled_.vulkan11, enabled_.vulkan12, enabled_.vulkan13);
    enabled_.features.features.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 supported2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
    vkGetPhysicalDeviceFeatures2(physicalDevice, &supported2);
    if (supported.shaderInt64 && supported12.shaderBufferInt64Atomics)
        enabled_.features.features.shaderInt64 = enabled_.vulkan12.shaderBufferInt64Atomics = VK_TRUE;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    std::vector<const char*> extensions;
    if (options.swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled_.features};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    check(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool), "vkCreateCommandPool");
}

crowdgpu::Device HostDevice::libraryDevice() const {
    return {instance, physicalDevice, device, queueFamily, &enabled_.features};
}

std::uint64_t HostDevice::deviceLocalBytes() const {
    std::uint64_t largest = 0;
    for (std::uint32_t i = 0; i < memoryProperties.memoryHeapCount; ++i)
        if (memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            largest = std::max<std::uint64_t>(largest, memoryProperties.memoryHeaps[i].size);
    return largest;
}

int HostDevice::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags flags) const {
    for (std::uint32_t i = 0; i < memoryProperties.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memoryProperties.memoryTypes[i].propertyFlags & flags) == flags)
            return static_cast<int>(i);
    return -1;
}

void HostDevice::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = commandPool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device, &allocate, &cmd), "vkAllocateCommandBuffers");
    VkFence fence = VK_NULL_HANDLE;
    try {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
        record(cmd);
        check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        check(vkCreateFence(device, &fenceInfo, nullptr, &fence), "vkCreateFence");
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        check(vkQueueSubmit(queue, 1, &submit, fence), "vkQueueSubmit");
        check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    } catch (...) {
        vkDeviceWaitIdle(device);
        if (fence) vkDestroyFence(device, fence, nullptr);
        vkFreeCommandBuffers(device, commandPool, 1, &cmd);
        throw;
    }
    vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, commandPool, 1, &cmd);
}

}  // namespace app
