// What a host's device must have for crowdgpu, and the checks of a borrowed device.
#include "api/device_requirements.h"

#include "api/api_data.h"
#include "crowdgpu/renderer.hpp"

namespace crowdgpu {
namespace {

// Every feature as (name, supported-or-enabled bit): one list for the requirements, the physical
// device check and the enabled-feature check, so the three cannot disagree.
struct FeatureBits {
    const char* name;
    VkBool32 value;
};

std::vector<FeatureBits> featureBits(const VkPhysicalDeviceFeatures2& f, const VkPhysicalDeviceVulkan11Features& f11,
                                     const VkPhysicalDeviceVulkan12Features& f12,
                                     const VkPhysicalDeviceVulkan13Features& f13) {
    // Dynamic rendering into the host's pass, synchronization2 barriers, draws that find their
    // character by firstInstance and their vertex by gl_BaseVertex, culling's indirect counts.
    return {{"dynamicRendering", f13.dynamicRendering},
            {"synchronization2", f13.synchronization2},
            {"shaderDrawParameters", f11.shaderDrawParameters},
            {"drawIndirectCount", f12.drawIndirectCount},
            {"multiDrawIndirect", f.features.multiDrawIndirect},
            {"drawIndirectFirstInstance", f.features.drawIndirectFirstInstance}};
}

// Finds a struct of type `type` in a pNext chain.
const void* findInChain(const void* chain, VkStructureType type) {
    for (auto* s = static_cast<const VkBaseInStructure*>(chain); s; s = s->pNext)
        if (s->sType == type) return s;
    return nullptr;
}

}  // namespace

DeviceRequirements deviceRequirements() {
    DeviceRequirements r{VK_API_VERSION_1_3, {}, {}};
    const VkPhysicalDeviceFeatures2 f{};
    const VkPhysicalDeviceVulkan11Features f11{};
    const VkPhysicalDeviceVulkan12Features f12{};
    const VkPhysicalDeviceVulkan13Features f13{};
    for (const FeatureBits& bit : featureBits(f, f11, f12, f13)) r.features.push_back(bit.name);
    return r;
}

void enableRequiredFeatures(VkPhysicalDeviceFeatures2& f, VkPhysicalDeviceVulkan11Features& f11,
                            VkPhysicalDeviceVulkan12Features& f12, VkPhysicalDeviceVulkan13Features& f13) {
    f13.dynamicRendering = f13.synchronization2 = VK_TRUE;
    f11.shaderDrawParameters = VK_TRUE;
    f12.drawIndirectCount = VK_TRUE;
    f.features.multiDrawIndirect = f.features.drawIndirectFirstInstance = VK_TRUE;
}

std::string checkPhysicalDevice(VkPhysicalDevice physicalDevice) {
    if (!physicalDevice) return "no physical device given";
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_3)
        return std::string(properties.deviceName) + " supports Vulkan " +
               std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
               std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + "; crowdgpu needs 1.3";
    VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f11};
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &f12};
    VkPhysicalDeviceFeatures2 f{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f13};
    vkGetPhysicalDeviceFeatures2(physicalDevice, &f);
    for (const FeatureBits& bit : featureBits(f, f11, f12, f13))
        if (!bit.value) return std::string(properties.deviceName) + " lacks the feature " + bit.name;
    return {};
}

namespace detail {

gpu::BorrowedHandles checkBorrowedDevice(const Device& device) {
    if (!device.instance || !device.physicalDevice || !device.device)
        throw Error(ErrorCode::InvalidArgument, "Device: instance, physicalDevice and device must all be given");
    if (const std::string problem = checkPhysicalDevice(device.physicalDevice); !problem.empty())
        throw Error(ErrorCode::Unsupported, problem);
    if (!device.enabledFeatures || device.enabledFeatures->sType != VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
        throw Error(ErrorCode::InvalidArgument,
                    "Device::enabledFeatures must point at the VkPhysicalDeviceFeatures2 chain the device was created with");
    const auto* f11 = static_cast<const VkPhysicalDeviceVulkan11Features*>(
        findInChain(device.enabledFeatures->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES));
    const auto* f12 = static_cast<const VkPhysicalDeviceVulkan12Features*>(
        findInChain(device.enabledFeatures->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES));
    const auto* f13 = static_cast<const VkPhysicalDeviceVulkan13Features*>(
        findInChain(device.enabledFeatures->pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES));
    const VkPhysicalDeviceVulkan11Features none11{};
    const VkPhysicalDeviceVulkan12Features none12{};
    const VkPhysicalDeviceVulkan13Features none13{};
    for (const FeatureBits& bit : featureBits(*device.enabledFeatures, f11 ? *f11 : none11, f12 ? *f12 : none12,
                                              f13 ? *f13 : none13))
        if (!bit.value)
            throw Error(ErrorCode::Unsupported, std::string("the device was created without the feature ") + bit.name +
                                                    " (enableRequiredFeatures sets every one needed)");
    std::uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.physicalDevice, &familyCount, nullptr);
    if (device.queueFamily >= familyCount)
        throw Error(ErrorCode::InvalidArgument, "Device::queueFamily " + std::to_string(device.queueFamily) +
                                                    " does not exist (the device has " + std::to_string(familyCount) + ")");
    gpu::BorrowedHandles handles{device.instance, device.physicalDevice, device.device, device.queueFamily,
                                 device.enabledFeatures->features.fragmentStoresAndAtomics == VK_TRUE};
    // Optional: the compute rasterizer's 64-bit atomics (refused in one line without them).
    handles.int64Atomics = device.enabledFeatures->features.shaderInt64 == VK_TRUE && f12 &&
                           f12->shaderBufferInt64Atomics == VK_TRUE;
    return handles;
}

namespace {

// Whether `format` is a format of Vulkan 1.3's core (which the library asks for; it enables no format
// extension). Any other value would reach the driver's format query as an invalid enum first.
bool coreFormat(VkFormat format) {
    const auto v = static_cast<std::int64_t>(format);
    auto within = [v](std::int64_t first, std::int64_t last) { return v >= first && v <= last; };
    return within(VK_FORMAT_R4G4_UNORM_PACK8, VK_FORMAT_ASTC_12x12_SRGB_BLOCK) ||
           within(VK_FORMAT_G8B8G8R8_422_UNORM, VK_FORMAT_G16_B16_R16_3PLANE_444_UNORM) ||
           within(VK_FORMAT_G8_B8R8_2PLANE_444_UNORM, VK_FORMAT_G16_B16R16_2PLANE_444_UNORM) ||
           within(VK_FORMAT_A4R4G4B4_UNORM_PACK16, VK_FORMAT_A4B4G4R4_UNORM_PACK16) ||
           within(VK_FORMAT_ASTC_4x4_SFLOAT_BLOCK, VK_FORMAT_ASTC_12x12_SFLOAT_BLOCK);
}

// S8_UINT is a depth-stencil attachment format with no depth.
bool hasDepth(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM: case VK_FORMAT_X8_D24_UNORM_PACK32: case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D16_UNORM_S8_UINT: case VK_FORMAT_D24_UNORM_S8_UINT: case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return true;
        default: return false;
    }
}

}  // namespace

void checkTargetFormat(VkPhysicalDevice physicalDevice, const TargetFormat& target) {
    // The values first (a C host may pass any integer), then what the device does with them.
    if (!coreFormat(target.color))
        throw Error(ErrorCode::InvalidArgument, "target colour format " + std::to_string(target.color) +
                                                    " is not a Vulkan 1.3 format");
    if (!coreFormat(target.depth))
        throw Error(ErrorCode::InvalidArgument, "target depth format " + std::to_string(target.depth) +
                                                    " is not a Vulkan 1.3 format");
    VkFormatProperties colour, depth;
    vkGetPhysicalDeviceFormatProperties(physicalDevice, target.color, &colour);
    vkGetPhysicalDeviceFormatProperties(physicalDevice, target.depth, &depth);
    if (!(colour.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT))
        throw Error(ErrorCode::Unsupported, "target colour format " + std::to_string(target.color) +
                                                " cannot be rendered to on this device");
    if (!hasDepth(target.depth) || !(depth.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
        throw Error(ErrorCode::Unsupported, "target depth format " + std::to_string(target.depth) +
                                                " is not a depth format this device renders to");
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    const VkSampleCountFlags samples =
        properties.limits.framebufferColorSampleCounts & properties.limits.framebufferDepthSampleCounts;
    if (!(samples & target.samples) || (target.samples & (target.samples - 1)) != 0)
        throw Error(ErrorCode::Unsupported, "target sample count " + std::to_string(target.samples) +
                                                " is not supported for colour and depth on this device");
}

}  // namespace detail
}  // namespace crowdgpu
