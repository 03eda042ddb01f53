// embed_headless: a minimal host of crowdgpu, as an application would write it.
//
// The host owns everything Vulkan: instance, device, queue, command buffers, fences and the images
// it draws into. crowdgpu records into the host's command buffers:
//   - a ground quad and boxes of the host's own pipeline are drawn in the same dynamic-rendering
//     pass as the crowd (Renderer::recordCharacters), into a B8G8R8A8_SRGB + D32_SFLOAT target;
//   - a second pass of the host's own reads Renderer::output() (the skinned vertices and the
//     renderer's indirect draws) and writes each visible character's index + 1 into an R32_UINT
//     ID image (for picking, outlines, ...).
// Two frames in flight, a fence per frame slot. At the end the colour and ID images are read back
// and written as <out>/crowd.ppm (RGB) and <out>/ids.pgm (16-bit: character index + 1, 0 = none).
//
// It also times its frames as crowdgpu's programs time theirs (timestamp queries in its own command
// buffers, frame_timer.hpp) and can draw the same frames as they do (scenes.hpp), so that a script
// can show what the library costs inside a host against what it costs in crowd-bench.
//
//   embed_headless [options] [out-dir] [WIDTHxHEIGHT] [frames]     (options.hpp; defaults: . 640x360 8)
//   CROWDGPU_VALIDATION=1 turns on the Khronos validation layer with synchronization validation;
//   the program then fails if the layer reported anything.
#include <crowdgpu/renderer.hpp>
#include <vulkan/vulkan.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "frame_timer.hpp"
#include "id.frag.h"
#include "id.vert.h"
#include "options.hpp"
#include "scene.frag.h"
#include "scene.vert.h"
#include "scenes.hpp"
#include "timing_report.hpp"

namespace {

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "embed_headless: %s\n", message.c_str());
    std::exit(1);
}

#define CHECK(call)                                                                              \
    do {                                                                                         \
        const VkResult result_ = (call);                                                         \
        if (result_ != VK_SUCCESS) fail(std::string(#call) + " returned " + std::to_string(result_)); \
    } while (0)

constexpr std::uint32_t kFramesInFlight = 2;
constexpr VkFormat kColorFormat = VK_FORMAT_B8G8R8A8_SRGB;  // not the library's default (R8G8B8A8_SRGB)
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kIdFormat = VK_FORMAT_R32_UINT;
constexpr float kSky[4] = {0.55f, 0.7f, 0.9f, 1.0f};  // linear
constexpr float kGround[3] = {0.30f, 0.30f, 0.28f};
constexpr float kBox[3] = {0.90f, 0.25f, 0.02f};  // orange; faces are shaded by a factor

// ---- Validation: count every message the layer reports ----

int validationMessages = 0;

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    ++validationMessages;
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
    return VK_FALSE;
}

// ---- The host's device ----

struct Gpu {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;
    VkQueue queue = VK_NULL_HANDLE;
    // The feature chain the device is created with; crowdgpu checks it (Device::enabledFeatures).
    VkPhysicalDeviceVulkan11Features vulkan11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
};

void createInstance(Gpu& gpu, bool validation) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "embed_headless";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;

    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    // Synchronization validation is off by default in the layer.
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT validationFeatures{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validationFeatures.enabledValidationFeatureCount = 1;
    validationFeatures.pEnabledValidationFeatures = enables;
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onValidationMessage;
    if (validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &layer;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &extension;
        messenger.pNext = &validationFeatures;
        info.pNext = &messenger;  // messages during vkCreateInstance count too
    }
    CHECK(vkCreateInstance(&info, nullptr, &gpu.instance));
    if (validation) {
        messenger.pNext = nullptr;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(gpu.instance, "vkCreateDebugUtilsMessengerEXT"));
        CHECK(create(gpu.instance, &messenger, nullptr, &gpu.messenger));
    }
}

// The first Vulkan 1.3 device with everything crowdgpu needs and a graphics + compute queue, whose
// name contains `name` (any name when empty).
void pickDevice(Gpu& gpu, const std::string& name) {
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
    for (VkPhysicalDevice device : devices) {
        if (!crowdgpu::checkPhysicalDevice(device).empty()) continue;  // not 1.3, or a feature missing
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        if (std::string(properties.deviceName).find(name) == std::string::npos) continue;
        std::uint32_t familyCount = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, nullptr);
        std::vector<VkQueueFamilyProperties> families(familyCount);
        vkGetPhysicalDeviceQueueFamilyProperties(device, &familyCount, families.data());
        for (std::uint32_t f = 0; f < familyCount; ++f) {
            if ((families[f].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
                gpu.physicalDevice = device;
                gpu.queueFamily = f;
                return;
            }
        }
    }
    fail("no Vulkan 1.3 device with the features crowdgpu needs" + (name.empty() ? "" : " named like '" + name + "'"));
}

void createDevice(Gpu& gpu) {
    // Chain 1.1, 1.2 and 1.3 features and let crowdgpu set the ones it needs (add your own too).
    gpu.vulkan12.pNext = &gpu.vulkan11;
    gpu.vulkan13.pNext = &gpu.vulkan12;
    gpu.features.pNext = &gpu.vulkan13;
    crowdgpu::enableRequiredFeatures(gpu.features, gpu.vulkan11, gpu.vulkan12, gpu.vulkan13);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = gpu.queueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &gpu.features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    CHECK(vkCreateDevice(gpu.physicalDevice, &info, nullptr, &gpu.device));
    vkGetDeviceQueue(gpu.device, gpu.queueFamily, 0, &gpu.queue);
}

// ---- Memory, buffers, images ----

VkDeviceMemory allocate(const Gpu& gpu, VkMemoryRequirements requirements, VkMemoryPropertyFlags properties) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(gpu.physicalDevice, &memory);
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((requirements.memoryTypeBits & (1u << i)) &&
            (memory.memoryTypes[i].propertyFlags & properties) == properties) {
            VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
            info.allocationSize = requirements.size;
            info.memoryTypeIndex = i;
            VkDeviceMemory result;
            CHECK(vkAllocateMemory(gpu.device, &info, nullptr, &result));
            return result;
        }
    }
    fail("no memory type fits");
}

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
};

// Host-visible and mapped: this example's buffers are small (vertices, readback).
Buffer createHostBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
    Buffer b;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    CHECK(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(gpu.device, b.buffer, &requirements);
    b.memory = allocate(gpu, requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    CHECK(vkBindBufferMemory(gpu.device, b.buffer, b.memory, 0));
    CHECK(vkMapMemory(gpu.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

void destroy(const Gpu& gpu, Buffer& b) {
    vkDestroyBuffer(gpu.device, b.buffer, nullptr);
    vkFreeMemory(gpu.device, b.memory, nullptr);
}

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};

Image createImage(const Gpu& gpu, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                  VkImageAspectFlags aspect) {
    Image image;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    CHECK(vkCreateImage(gpu.device, &info, nullptr, &image.image));
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(gpu.device, image.image, &requirements);
    image.memory = allocate(gpu, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    CHECK(vkBindImageMemory(gpu.device, image.image, image.memory, 0));
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    CHECK(vkCreateImageView(gpu.device, &view, nullptr, &image.view));
    return image;
}

void destroy(const Gpu& gpu, Image& image) {
    vkDestroyImageView(gpu.device, image.view, nullptr);
    vkDestroyImage(gpu.device, image.image, nullptr);
    vkFreeMemory(gpu.device, image.memory, nullptr);
}

// One image barrier (synchronization2).
void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
             VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
             VkImageLayout oldLayout, VkImageLayout newLayout) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = srcStage;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dstStage;
    b.dstAccessMask = dstAccess;
    b.oldLayout = oldLayout;
    b.newLayout = newLayout;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

// ---- The host's pipelines ----

VkShaderModule shaderModule(const Gpu& gpu, const std::uint32_t* code, std::size_t bytes) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module;
    CHECK(vkCreateShaderModule(gpu.device, &info, nullptr, &module));
    return module;
}

struct PipelineDesc {
    const std::uint32_t* vertexCode;
    std::size_t vertexBytes;
    const std::uint32_t* fragmentCode;
    std::size_t fragmentBytes;
    VkVertexInputBindingDescription binding;
    std::vector<VkVertexInputAttributeDescription> attributes;
    VkFormat colorFormat;
    bool depthWrite;
    VkCompareOp depthCompare;
};

// A pipeline for dynamic rendering into (colorFormat, kDepthFormat); viewport and scissor dynamic.
VkPipeline createPipeline(const Gpu& gpu, VkPipelineLayout layout, const PipelineDesc& d) {
    const VkShaderModule vertex = shaderModule(gpu, d.vertexCode, d.vertexBytes);
    const VkShaderModule fragment = shaderModule(gpu, d.fragmentCode, d.fragmentBytes);
    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    stages[1].pName = "main";

    VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &d.binding;
    vertexInput.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(d.attributes.size());
    vertexInput.pVertexAttributeDescriptions = d.attributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = d.depthWrite ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = d.depthCompare;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &d.colorFormat;
    rendering.depthAttachmentFormat = kDepthFormat;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    VkPipeline pipeline;
    CHECK(vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    vkDestroyShaderModule(gpu.device, vertex, nullptr);
    vkDestroyShaderModule(gpu.device, fragment, nullptr);
    return pipeline;
}

// ---- The host's scene: a ground quad and a few boxes ----

struct SceneVertex {
    float position[3];
    float color[3];
};

void addQuad(std::vector<SceneVertex>& out, const float (&corners)[4][3], const float color[3], float shade) {
    const float c[3] = {color[0] * shade, color[1] * shade, color[2] * shade};
    for (int i : {0, 1, 2, 0, 2, 3})
        out.push_back({{corners[i][0], corners[i][1], corners[i][2]}, {c[0], c[1], c[2]}});
}

void addBox(std::vector<SceneVertex>& out, float x, float z, float size, float height) {
    const float h = size / 2;
    const float x0 = x - h, x1 = x + h, z0 = z - h, z1 = z + h, y1 = height;
    // Top, then the four sides, each a little darker so the box reads as one.
    addQuad(out, {{x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}}, kBox, 1.0f);
    addQuad(out, {{x0, 0, z1}, {x1, 0, z1}, {x1, y1, z1}, {x0, y1, z1}}, kBox, 0.8f);
    addQuad(out, {{x0, 0, z0}, {x1, 0, z0}, {x1, y1, z0}, {x0, y1, z0}}, kBox, 0.8f);
    addQuad(out, {{x1, 0, z0}, {x1, 0, z1}, {x1, y1, z1}, {x1, y1, z0}}, kBox, 0.6f);
    addQuad(out, {{x0, 0, z0}, {x0, 0, z1}, {x0, y1, z1}, {x0, y1, z0}}, kBox, 0.6f);
}

// Column-major 4x4 product a * b.
std::array<float, 16> multiply(const float* a, const float* b) {
    std::array<float, 16> r{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) r[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
    return r;
}

// ---- Output files ----

void writePpm(const std::string& path, VkExtent2D extent, const std::uint8_t* bgra) {
    std::ofstream file(path, std::ios::binary);
    file << "P6\n" << extent.width << " " << extent.height << "\n255\n";
    for (std::uint32_t i = 0; i < extent.width * extent.height; ++i) {
        const char rgb[3] = {static_cast<char>(bgra[i * 4 + 2]), static_cast<char>(bgra[i * 4 + 1]),
                             static_cast<char>(bgra[i * 4 + 0])};
        file.write(rgb, 3);
    }
    if (!file) fail("cannot write " + path);
}

// 16-bit binary PGM (big-endian samples): the character index + 1, 0 where no character is.
void writePgm16(const std::string& path, VkExtent2D extent, const std::uint32_t* ids) {
    std::ofstream file(path, std::ios::binary);
    file << "P5\n" << extent.width << " " << extent.height << "\n65535\n";
    for (std::uint32_t i = 0; i < extent.width * extent.height; ++i) {
        const std::uint32_t id = ids[i] > 65535 ? 65535 : ids[i];
        const char sample[2] = {static_cast<char>(id >> 8), static_cast<char>(id & 0xff)};
        file.write(sample, 2);
    }
    if (!file) fail("cannot write " + path);
}

// The host's geometry for its view of the crowd: ground around the crowd, two boxes in front of it
// and one behind.
std::vector<SceneVertex> hostGeometry(const crowdgpu::Crowd& crowd) {
    float center[3], radius, tallest;
    crowd.bounds(center, radius, tallest);
    std::vector<SceneVertex> vertices;
    const float g = 1.6f * radius + 2.0f * tallest;
    addQuad(vertices,
            {{center[0] - g, 0, center[2] - g}, {center[0] + g, 0, center[2] - g},
             {center[0] + g, 0, center[2] + g}, {center[0] - g, 0, center[2] + g}},
            kGround, 1.0f);
    addBox(vertices, center[0] - 0.55f * radius, center[2] + radius + 1.0f, 1.2f, 1.2f);
    addBox(vertices, center[0] + 0.55f * radius, center[2] + radius + 1.0f, 1.2f, 1.2f);
    addBox(vertices, center[0], center[2] - radius - 2.0f, 2.0f, 3.0f);
    return vertices;
}

// ---- One frame's commands ----

// The host's images: colour and depth of the crowd's pass, and the ID image of its own pass.
struct Target {
    VkExtent2D extent;
    Image color, depth, ids;
};

// What the host draws itself: its ground and boxes in the crowd's pass, and the ID pass.
struct HostDrawing {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline scene = VK_NULL_HANDLE;
    VkPipeline id = VK_NULL_HANDLE;
    Buffer vertices;
    std::uint32_t vertexCount = 0;
};

void setViewportAndScissor(VkCommandBuffer cmd, VkExtent2D extent) {
    const VkViewport viewport{0, 0, float(extent.width), float(extent.height), 0, 1};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, VkAttachmentLoadOp load,
                                     VkAttachmentStoreOp store) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = view;
    info.imageLayout = layout;
    info.loadOp = load;
    info.storeOp = store;
    return info;
}

const VkPipelineStageFlags2 kFragmentTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

// The colour pass: the host's ground and boxes (or, with `host` null, the library's ground as
// crowd-render draws it), then the crowd. The images are shared by both frame slots: wait for the
// previous frame's writes before clearing them.
void recordColourPass(VkCommandBuffer cmd, const Target& target, crowdgpu::Renderer& renderer, std::uint32_t slot,
                      const HostDrawing* host, const std::array<float, 16>& viewProjection) {
    std::vector<VkImage> colourImages{target.color.image};
    if (host) colourImages.push_back(target.ids.image);  // cleared by the ID pass
    for (VkImage image : colourImages)
        barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
                VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    barrier(cmd, target.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, kFragmentTests,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kFragmentTests,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
            VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);

    // The library's frame ends with its sky on every pixel nothing else drew (RendererSettings::sky), so
    // the colour needs no clear, whose fill costs 8 % of paper-fig4's frame on an H200. The host's own
    // scene leaves sky uncovered and keeps the library's sky off: it clears.
    VkRenderingAttachmentInfo colour =
        attachment(target.color.view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   host ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_STORE);
    std::memcpy(colour.clearValue.color.float32, kSky, sizeof kSky);
    // The ID pass tests against this depth; without it nothing reads it after the pass.
    VkRenderingAttachmentInfo depth =
        attachment(target.depth.view, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_ATTACHMENT_LOAD_OP_CLEAR,
                   host ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE);
    depth.clearValue.depthStencil = {1.0f, 0};  // crowdgpu: depth 1 is far, tested with LESS
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, target.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &colour;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);
    if (host) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, host->scene);
        setViewportAndScissor(cmd, target.extent);
        vkCmdPushConstants(cmd, host->layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof viewProjection,
                           viewProjection.data());
        const VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &host->vertices.buffer, &zero);
        vkCmdDraw(cmd, host->vertexCount, 1, 0, 0);
    }
    // The renderer binds its own pipelines and state; a host rebinds its own after it. Without the
    // host's scene it draws its checkered ground behind the characters (RendererSettings::ground).
    renderer.recordCharacters(cmd, slot);
    vkCmdEndRendering(cmd);
}

// The ID pass over the renderer's output, tested against the colour pass's depth so only visible
// characters get an ID.
void recordIdPass(VkCommandBuffer cmd, const Target& target, const crowdgpu::Renderer& renderer,
                  const HostDrawing& host, const std::array<float, 16>& viewProjection) {
    barrier(cmd, target.depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, kFragmentTests,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, kFragmentTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo ids = attachment(target.ids.view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                               VK_ATTACHMENT_LOAD_OP_CLEAR,  // 0: no character
                                               VK_ATTACHMENT_STORE_OP_STORE);
    VkRenderingAttachmentInfo depth = attachment(target.depth.view, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                                 VK_ATTACHMENT_LOAD_OP_LOAD,
                                                 VK_ATTACHMENT_STORE_OP_NONE);  // read only here
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, target.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &ids;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &rendering);
    const crowdgpu::FrameOutput out = renderer.output();
    if (out.skinned) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, host.id);
        setViewportAndScissor(cmd, target.extent);
        vkCmdPushConstants(cmd, host.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof viewProjection,
                           viewProjection.data());
        vkCmdBindVertexBuffers(cmd, 0, 1, &out.vertices, &out.positionsOffset);
        vkCmdBindIndexBuffer(cmd, out.indices, 0, VK_INDEX_TYPE_UINT32);
        // The renderer's own draws after culling and LOD: one per visible character, and those fading
        // between two levels (lodFade) from their own list.
        vkCmdDrawIndexedIndirectCount(cmd, out.draws, 0, out.drawCount, out.drawCountOffset, out.maxDraws,
                                      sizeof(VkDrawIndexedIndirectCommand));
        vkCmdDrawIndexedIndirectCount(cmd, out.draws, out.fadingDrawsOffset, out.drawCount, out.fadingCountOffset,
                                      out.maxDraws, sizeof(VkDrawIndexedIndirectCommand));
    }
    vkCmdEndRendering(cmd);
}

// After the last frame: copies the colour image (and the ID image, when `ids` is given) to host memory.
void recordReadback(VkCommandBuffer cmd, const Target& target, const Buffer& colour, const Buffer* ids) {
    std::vector<std::pair<VkImage, VkBuffer>> copies{{target.color.image, colour.buffer}};
    if (ids) copies.emplace_back(target.ids.image, ids->buffer);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target.extent.width, target.extent.height, 1};
    for (const auto& [image, buffer] : copies) {
        barrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    }
    VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &toHost;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

double nowMs() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parseOptions(argc, argv);
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "embed_headless: %s\n%s", error.what(), usage());
        return 1;
    }
    const VkExtent2D extent = options.extent;
    const char* validationEnv = std::getenv("CROWDGPU_VALIDATION");
    const bool validation = validationEnv && std::strcmp(validationEnv, "1") == 0;

    Gpu gpu;
    createInstance(gpu, validation);
    pickDevice(gpu, options.device);
    createDevice(gpu);

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = gpu.queueFamily;
    VkCommandPool pool;
    CHECK(vkCreateCommandPool(gpu.device, &poolInfo, nullptr, &pool));
    std::array<VkCommandBuffer, kFramesInFlight> commands;
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = pool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = kFramesInFlight;
    CHECK(vkAllocateCommandBuffers(gpu.device, &allocateInfo, commands.data()));
    std::array<VkFence, kFramesInFlight> fences;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first wait on each slot returns at once
    for (VkFence& fence : fences) CHECK(vkCreateFence(gpu.device, &fenceInfo, nullptr, &fence));

    // The host's target: colour, depth (shared by both passes) and the ID image.
    Target target{extent,
                  createImage(gpu, extent, kColorFormat,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT),
                  createImage(gpu, extent, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                              VK_IMAGE_ASPECT_DEPTH_BIT),
                  createImage(gpu, extent, kIdFormat,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              VK_IMAGE_ASPECT_COLOR_BIT)};
    const VkDeviceSize pixelBytes = VkDeviceSize(extent.width) * extent.height * 4;
    Buffer colorReadback = createHostBuffer(gpu, pixelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    Buffer idReadback = createHostBuffer(gpu, pixelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    int status = 0;
    try {
        // The crowd (Vulkan-free) and the renderer on the host's device, for the host's formats.
        crowdgpu::Crowd crowd = makeCrowd(options.count);
        crowdgpu::RendererSettings settings;
        settings.target.color = kColorFormat;
        settings.target.depth = kDepthFormat;
        settings.method = options.method;  // Compute, the default, skins into a buffer: output() has the vertices
        settings.framesInFlight = kFramesInFlight;
        settings.ground = options.crowdOnly;  // crowd-render's frame: the library's ground, not the host's,
        settings.sky = options.crowdOnly;     // and its sky, so that the colour pass needs no clear
        const crowdgpu::Device device{gpu.instance, gpu.physicalDevice, gpu.device, gpu.queueFamily, &gpu.features};
        crowdgpu::Renderer renderer(device, crowd, settings);

        // Setup (uploads): recorded by the renderer, submitted and waited for by the host, once.
        {
            VkCommandBuffer cmd = commands[0];
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            CHECK(vkBeginCommandBuffer(cmd, &begin));
            renderer.recordSetup(cmd);
            CHECK(vkEndCommandBuffer(cmd));
            VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            submit.commandBufferCount = 1;
            submit.pCommandBuffers = &cmd;
            CHECK(vkResetFences(gpu.device, 1, &fences[0]));
            CHECK(vkQueueSubmit(gpu.queue, 1, &submit, fences[0]));
            CHECK(vkWaitForFences(gpu.device, 1, &fences[0], VK_TRUE, UINT64_MAX));
            renderer.setupCompleted();
        }

        // GPU time per part of the frame: the renderer's passes (its observer marks each as it ends),
        // then the colour pass ("draw", where the crowd's work ends) and the host's ID pass ("id").
        FrameTimer timer(gpu.physicalDevice, gpu.device, gpu.queueFamily, kFramesInFlight);
        renderer.setPassObserver([&timer](VkCommandBuffer cmd, const char* pass) { timer.mark(cmd, pass); });
        TimingReport report("draw");

        // Two pipelines of the host's: the scene (into the colour pass) and the ID pass.
        const std::vector<SceneVertex> vertices = hostGeometry(crowd);
        HostDrawing host;
        host.vertexCount = static_cast<std::uint32_t>(vertices.size());
        host.vertices = createHostBuffer(gpu, vertices.size() * sizeof(SceneVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        std::memcpy(host.vertices.mapped, vertices.data(), vertices.size() * sizeof(SceneVertex));
        VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, 16 * sizeof(float)};
        VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layoutInfo.pushConstantRangeCount = 1;
        layoutInfo.pPushConstantRanges = &push;
        CHECK(vkCreatePipelineLayout(gpu.device, &layoutInfo, nullptr, &host.layout));
        host.scene = createPipeline(
            gpu, host.layout,
            {scene_vert_spv, sizeof scene_vert_spv, scene_frag_spv, sizeof scene_frag_spv,
             {0, sizeof(SceneVertex), VK_VERTEX_INPUT_RATE_VERTEX},
             {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, position)},
              {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(SceneVertex, color)}},
             kColorFormat, true, VK_COMPARE_OP_LESS});
        // The crowd's skinned positions are vec4s, 16 bytes apart (normals, also vec4, follow at
        // output().normalsOffset; this pass does not need them).
        host.id = createPipeline(
            gpu, host.layout,
            {id_vert_spv, sizeof id_vert_spv, id_frag_spv, sizeof id_frag_spv,
             {0, 4 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX},
             {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}},
             kIdFormat, false, VK_COMPARE_OP_LESS_OR_EQUAL});
        const HostDrawing* hostDrawing = options.crowdOnly ? nullptr : &host;

        // Warm-up frames, then the timed ones. A slot's timings are read once its fence has signalled,
        // just before the slot is recorded again (and for the last frames, at the end).
        const std::uint32_t frameCount = options.warmup + options.frames;
        std::vector<double> frameStarts(frameCount);
        std::array<std::int64_t, kFramesInFlight> frameInSlot;
        frameInSlot.fill(-1);
        auto collect = [&](std::uint32_t slot) {
            const std::int64_t frame = std::exchange(frameInSlot[slot], -1);
            if (frame < static_cast<std::int64_t>(options.warmup)) return;  // none, or a warm-up frame
            const double interval = frame > 0 ? frameStarts[frame] - frameStarts[frame - 1] : 0.0;
            report.add(timer.read(slot), interval, renderer.counts(slot));
        };
        for (std::uint32_t frame = 0; frame < frameCount; ++frame) {
            const std::uint32_t slot = frame % kFramesInFlight;
            const bool last = frame == frameCount - 1;
            const double time = frameTime(frame, options.start);
            frameStarts[frame] = nowMs();
            // Wait for this slot's previous frame: its command buffer and the renderer's slot are free.
            CHECK(vkWaitForFences(gpu.device, 1, &fences[slot], VK_TRUE, UINT64_MAX));
            collect(slot);
            CHECK(vkResetFences(gpu.device, 1, &fences[slot]));
            crowd.advanceTo(time);
            const CameraPose camera = cameraAt(options.scene, crowd, time);
            const crowdgpu::FrameView view = crowdgpu::lookAt(camera.eye, camera.target, camera.verticalFov,
                                                              camera.nearPlane, camera.farPlane, extent, time);
            const std::array<float, 16> viewProjection = multiply(view.projection, view.view);

            VkCommandBuffer cmd = commands[slot];
            VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
            begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            CHECK(vkBeginCommandBuffer(cmd, &begin));
            timer.begin(cmd, slot);
            // 1. The crowd's compute work and shadows, outside any pass.
            renderer.recordCompute(cmd, slot, view, crowd);
            renderer.recordShadows(cmd, slot);
            // 2. The colour pass: the host's ground and boxes (or the library's ground), then the crowd.
            recordColourPass(cmd, target, renderer, slot, hostDrawing, viewProjection);
            timer.mark(cmd, "draw");
            // 3. The host's ID pass over the renderer's output.
            if (hostDrawing) {
                recordIdPass(cmd, target, renderer, *hostDrawing, viewProjection);
                timer.mark(cmd, "id");
            }
            // 4. After the last frame: copy colour and IDs to host memory.
            if (last) recordReadback(cmd, target, colorReadback, hostDrawing ? &idReadback : nullptr);
            CHECK(vkEndCommandBuffer(cmd));
            VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
            submit.commandBufferCount = 1;
            submit.pCommandBuffers = &cmd;
            CHECK(vkQueueSubmit(gpu.queue, 1, &submit, fences[slot]));
            frameInSlot[slot] = frame;
        }
        // Wait for every slot's last frame (not vkDeviceWaitIdle: the fences say it all).
        CHECK(vkWaitForFences(gpu.device, kFramesInFlight, fences.data(), VK_TRUE, UINT64_MAX));
        for (std::uint32_t slot = 0; slot < kFramesInFlight; ++slot) collect(slot);

        // The outputs and a summary of what the last frame and the ID image show.
        writePpm(options.outDir + "/crowd.ppm", extent, static_cast<const std::uint8_t*>(colorReadback.mapped));
        const crowdgpu::FrameCounts counts = renderer.counts((frameCount - 1) % kFramesInFlight);
        std::printf("%s: %s, %u characters, %s, %ux%u, %u+%u frames, %u characters drawn (LOD %u/%u/%u)",
                    options.outDir.c_str(), sceneName(options.scene), crowd.size(),
                    options.crowdOnly ? "crowd only" : "with the host's boxes and ID pass", extent.width, extent.height,
                    options.warmup, options.frames, counts.characters[0] + counts.characters[1] + counts.characters[2],
                    counts.characters[0], counts.characters[1], counts.characters[2]);
        if (hostDrawing) {
            const auto* idPixels = static_cast<const std::uint32_t*>(idReadback.mapped);
            writePgm16(options.outDir + "/ids.pgm", extent, idPixels);
            std::set<std::uint32_t> seen;
            std::uint64_t crowdPixels = 0;
            for (std::uint32_t i = 0; i < extent.width * extent.height; ++i)
                if (idPixels[i] != 0) seen.insert(idPixels[i]), ++crowdPixels;
            std::printf(", %zu distinct ids, %llu crowd pixels", seen.size(),
                        static_cast<unsigned long long>(crowdPixels));
        }
        std::printf("\n");
        report.print(stdout);

        vkDestroyPipeline(gpu.device, host.id, nullptr);
        vkDestroyPipeline(gpu.device, host.scene, nullptr);
        vkDestroyPipelineLayout(gpu.device, host.layout, nullptr);
        destroy(gpu, host.vertices);
        // The timer, the renderer (and then the crowd) go here, before the device.
    } catch (const crowdgpu::Error& error) {
        std::fprintf(stderr, "embed_headless: crowdgpu: %s\n", error.what());
        status = 1;
    } catch (const std::runtime_error& error) {  // the frame timer's
        std::fprintf(stderr, "embed_headless: %s\n", error.what());
        status = 1;
    }

    destroy(gpu, idReadback);
    destroy(gpu, colorReadback);
    destroy(gpu, target.ids);
    destroy(gpu, target.depth);
    destroy(gpu, target.color);
    for (VkFence fence : fences) vkDestroyFence(gpu.device, fence, nullptr);
    vkDestroyCommandPool(gpu.device, pool, nullptr);
    vkDestroyDevice(gpu.device, nullptr);
    if (gpu.messenger) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(gpu.instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroyMessenger(gpu.instance, gpu.messenger, nullptr);
    }
    vkDestroyInstance(gpu.instance, nullptr);
    if (validationMessages > 0) {
        std::fprintf(stderr, "embed_headless: the validation layer reported %d message(s)\n", validationMessages);
        return 1;
    }
    return status;
}
