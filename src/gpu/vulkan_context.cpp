#include "gpu/vulkan_context.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "gpu/setup_queue.h"
#include "gpu/vulkan_error.h"

namespace gpu {

VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                        VkDebugUtilsMessageTypeFlagsEXT,
                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* context = static_cast<VulkanContext*>(user);
    context->validationMessageCount_++;
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

const char* typeName(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

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
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
    vkGetPhysicalDeviceProperties2(device, &properties);
    return {index, properties.properties.deviceName, typeName(properties.properties.deviceType),
            std::string(driver.driverName) + " " + driver.driverInfo, properties.properties.apiVersion};
}

VkInstance createBareInstance(const std::vector<const char*>& layers, const std::vector<const char*>& extensions,
                              const void* next) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "crowd-skinning";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, next};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
        throw Error("no Vulkan driver found (vkCreateInstance: " + std::string(resultName(result)) +
                    "); install mesa-vulkan-drivers for the CPU device lavapipe, or a GPU driver");
    VK_CHECK(result);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    return devices;
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

VulkanContext::VulkanContext(const ContextOptions& options) {
    try {
        createInstance(options);
        pickPhysicalDevice(options.deviceSelector);
        createDevice(options);
    } catch (...) {
        release();
        throw;
    }
}

VulkanContext::VulkanContext(const BorrowedHandles& borrowed)
    : instance(borrowed.instance),
      physicalDevice(borrowed.physicalDevice),
      device(borrowed.device),
      queueFamily(borrowed.queueFamily),
      multiDrawIndirect(true),
      fragmentStores(borrowed.fragmentStoresAndAtomics),
      setup_(std::make_unique<SetupQueue>()) {
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
    description = describe(physicalDevice, 0);
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    if (queueFamily < familyCount && families[queueFamily].timestampValidBits > 0)
        timestampPeriodNs_ = properties.limits.timestampPeriod;
}

VulkanContext::~VulkanContext() {
    if (setup_) {
        setup_.reset();  // the borrowed device is the host's to destroy, after the library
        return;
    }
    release();
}

void VulkanContext::release() {
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

void VulkanContext::createInstance(const ContextOptions& options) {
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
    if (options.validation) {
        if (!hasLayer(kValidationLayer))
            throw Error("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                        "(apt-get install vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        debugUtils_ = true;
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
    messengerInfo.pfnUserCallback = onValidationMessage;
    messengerInfo.pUserData = this;
    // Chained so messages during vkCreateInstance itself are counted too.
    messengerInfo.pNext = &features;
    instance = createBareInstance(layers, extensions, options.validation ? &messengerInfo : nullptr);
    if (options.validation) {
        messengerInfo.pNext = nullptr;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(instance, &messengerInfo, nullptr, &messenger_));
    }
}

void VulkanContext::pickPhysicalDevice(const std::string& selector) {
    const std::vector<VkPhysicalDevice> devices = physicalDevices(instance);
    if (devices.empty())
        throw Error("no Vulkan device found; install mesa-vulkan-drivers for the CPU device lavapipe");
    std::vector<DeviceDescription> descriptions;
    for (std::uint32_t i = 0; i < devices.size(); ++i) descriptions.push_back(describe(devices[i], i));

    int chosen = -1;
    if (selector.empty()) {
        int bestRank = 1 << 30;
        for (std::uint32_t i = 0; i < devices.size(); ++i) {
            VkPhysicalDeviceProperties p;
            vkGetPhysicalDeviceProperties(devices[i], &p);
            if (p.apiVersion < VK_API_VERSION_1_3) continue;
            if (typeRank(p.deviceType) < bestRank) bestRank = typeRank(p.deviceType), chosen = static_cast<int>(i);
        }
        if (chosen < 0) throw Error("no Vulkan 1.3 device found (" + descriptions[0].name + " is older)");
    } else if (std::all_of(selector.begin(), selector.end(), ::isdigit)) {
        const unsigned long index = std::stoul(selector);
        if (index >= devices.size())
            throw Error("--device " + selector + ": only " + std::to_string(devices.size()) +
                        " device(s); see --list-devices");
        chosen = static_cast<int>(index);
    } else {
        for (const DeviceDescription& d : descriptions)
            if (d.name.find(selector) != std::string::npos) { chosen = static_cast<int>(d.index); break; }
        if (chosen < 0) throw Error("--device " + selector + ": no device name contains it; see --list-devices");
    }
    physicalDevice = devices[static_cast<std::size_t>(chosen)];
    description = descriptions[static_cast<std::size_t>(chosen)];
    if (description.apiVersion < VK_API_VERSION_1_3)
        throw Error("device " + description.name + " supports only Vulkan " +
                    std::to_string(VK_API_VERSION_MAJOR(description.apiVersion)) + "." +
                    std::to_string(VK_API_VERSION_MINOR(description.apiVersion)) + "; 1.3 is required");
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);
}

void VulkanContext::createDevice(const ContextOptions& options) {
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    bool found = false;
    for (std::uint32_t i = 0; i < familyCount && !found; ++i) {
        const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & needed) == needed) queueFamily = i, found = true;
    }
    if (!found) throw Error("device " + description.name + " has no graphics+compute queue");
    if (families[queueFamily].timestampValidBits > 0) timestampPeriodNs_ = properties.limits.timestampPeriod;

    VkPhysicalDeviceVulkan11Features supported11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &supported11};
    VkPhysicalDeviceVulkan13Features supported13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &supported12};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported13};
    vkGetPhysicalDeviceFeatures2(physicalDevice, &supported);
    if (!supported13.dynamicRendering || !supported13.synchronization2)
        throw Error("device " + description.name + " lacks dynamicRendering or synchronization2");
    // Pass 2 finds a vertex's texture coordinates from gl_VertexIndex - gl_BaseVertex.
    if (!supported11.shaderDrawParameters)
        throw Error("device " + description.name + " lacks shaderDrawParameters");
    // The GPU-driven frame: culling writes indirect draws with their count, a first instance that names
    // the character, several draws per call.
    const VkPhysicalDeviceFeatures& core = supported.features;
    if (!supported12.drawIndirectCount || !core.multiDrawIndirect || !core.drawIndirectFirstInstance)
        throw Error("device " + description.name +
                    " lacks drawIndirectCount, multiDrawIndirect or drawIndirectFirstInstance");
    multiDrawIndirect = true;
    fragmentStores = supported.features.fragmentStoresAndAtomics;

    VkPhysicalDeviceVulkan11Features enabled11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    enabled11.shaderDrawParameters = VK_TRUE;
    VkPhysicalDeviceVulkan12Features enabled12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &enabled11};
    enabled12.drawIndirectCount = VK_TRUE;
    VkPhysicalDeviceVulkan13Features enabled13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &enabled12};
    enabled13.dynamicRendering = VK_TRUE;
    enabled13.synchronization2 = VK_TRUE;
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &enabled13};
    enabled.features.multiDrawIndirect = VK_TRUE;
    enabled.features.drawIndirectFirstInstance = VK_TRUE;
    enabled.features.fragmentStoresAndAtomics = supported.features.fragmentStoresAndAtomics;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    std::vector<const char*> extensions;
    if (options.swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(physicalDevice, &info, nullptr, &device));
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
}

std::uint64_t VulkanContext::deviceLocalBytes() const {
    std::uint64_t largest = 0;
    for (std::uint32_t i = 0; i < memoryProperties.memoryHeapCount; ++i)
        if (memoryProperties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            largest = std::max<std::uint64_t>(largest, memoryProperties.memoryHeaps[i].size);
    return largest;
}

void VulkanContext::setDebugName(VkObjectType type, std::uint64_t handle, const char* name) const {
    if (!debugUtils_) return;
    auto setName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    setName(device, &info);
}

}  // namespace gpu
