/* The C API compiled as C11: a host in C creates its instance (validation layer with synchronization
 * validation; any message fails) and device, builds a soldier crowd, creates a renderer with the
 * library's default formats, records setup and a few frames into its own offscreen target, reads the
 * image back and checks the crowd is in it; and checks the error codes of misuse. Exit 0: all well. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <vulkan/vulkan.h>

#include "crowdgpu/crowdgpu.h"

#define FRAMES_IN_FLIGHT 2
#define FRAMES 3
#define WIDTH 160
#define HEIGHT 120

static int failures = 0;
static int validation_messages = 0;

#define VK_CHECK(call)                                                           \
    do {                                                                         \
        VkResult result_ = (call);                                               \
        if (result_ != VK_SUCCESS) {                                             \
            fprintf(stderr, "%s:%d: %s returned %d\n", __FILE__, __LINE__, #call, result_); \
            exit(1);                                                             \
        }                                                                        \
    } while (0)

#define EXPECT(condition, ...)                                       \
    do {                                                             \
        if (!(condition)) {                                          \
            fprintf(stderr, "%s:%d: FAILED: ", __FILE__, __LINE__); \
            fprintf(stderr, __VA_ARGS__);                            \
            fprintf(stderr, "\n");                                   \
            ++failures;                                              \
        }                                                            \
    } while (0)

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    (void)severity, (void)types, (void)user;
    ++validation_messages;
    fprintf(stderr, "validation: %s\n", data->pMessage);
    return VK_FALSE;
}

static uint32_t memory_type(VkPhysicalDevice physical, uint32_t bits, VkMemoryPropertyFlags flags) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    fprintf(stderr, "no memory type\n");
    exit(1);
}

static VkImage create_image(VkPhysicalDevice physical, VkDevice device, VkFormat format, VkImageUsageFlags usage,
                            VkImageAspectFlags aspect, VkDeviceMemory* memory, VkImageView* view) {
    VkImageCreateInfo info = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = (VkExtent3D){WIDTH, HEIGHT, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    VkImage image;
    VK_CHECK(vkCreateImage(device, &info, NULL, &image));
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image, &requirements);
    VkMemoryAllocateInfo allocate = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = memory_type(physical, requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VK_CHECK(vkAllocateMemory(device, &allocate, NULL, memory));
    VK_CHECK(vkBindImageMemory(device, image, *memory, 0));
    VkImageViewCreateInfo view_info = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = format;
    view_info.subresourceRange = (VkImageSubresourceRange){aspect, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(device, &view_info, NULL, view));
    return image;
}

static void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 src_stage,
                          VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access,
                          VkImageLayout old_layout, VkImageLayout new_layout) {
    VkImageMemoryBarrier2 barrier = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = src_stage;
    barrier.srcAccessMask = src_access;
    barrier.dstStageMask = dst_stage;
    barrier.dstAccessMask = dst_access;
    barrier.oldLayout = old_layout;
    barrier.newLayout = new_layout;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = (VkImageSubresourceRange){aspect, 0, 1, 0, 1};
    VkDependencyInfo dependency = {VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

/* The host's world in C (issue 40), each call against what C++ does: a capacity of slots, handles that go
 * stale, batches all or none, samples from the host's memory, terrain; every refusal its code and line. */
static void host_world_in_c(void) {
    crowdgpu_model soldier = NULL;
    EXPECT(crowdgpu_model_soldier(1, &soldier) == CROWDGPU_OK, "soldier: %s", crowdgpu_last_error());
    const crowdgpu_character walker = {0, 0, 0.0f, 1.0f, {0.0f, 0.0f, 0.0f}, 0.0f, 1.0f, {1.0f, 1.0f, 1.0f},
                                       CROWDGPU_MOTION_BEHAVIOUR};
    crowdgpu_character initial[2] = {walker, walker};
    initial[1].motion = CROWDGPU_MOTION_HOST_SAMPLES;
    initial[1].position[0] = 2.0f;
    const uint32_t most[1] = {3};
    const crowdgpu_capacity capacity = {most, 0}; /* 0 keys: 8, since a character is driven */
    crowdgpu_crowd crowd = NULL;
    EXPECT(crowdgpu_crowd_create(&soldier, 1, initial, 2, &capacity, 1, CROWDGPU_IN_PLACE, &crowd) == CROWDGPU_OK,
           "a crowd of 2 in 3 slots: %s", crowdgpu_last_error());
    EXPECT(crowdgpu_crowd_size(crowd) == 3 && crowdgpu_crowd_live_count(crowd) == 2, "3 slots, 2 living");

    /* Spawn into the spare slot; past the capacity, its own code, nothing changed. */
    crowdgpu_handle third = {0, 0}, batch[2] = {{0, 0}, {0, 0}};
    EXPECT(crowdgpu_crowd_spawn(crowd, &walker, &third) == CROWDGPU_OK && third.slot == 2 && third.generation == 1,
           "spawn: slot %u generation %u: %s", third.slot, third.generation, crowdgpu_last_error());
    EXPECT(crowdgpu_crowd_spawn(crowd, &walker, NULL) == CROWDGPU_ERROR_CAPACITY_EXCEEDED &&
               strstr(crowdgpu_last_error(), "taken") != NULL,
           "a spawn past the capacity: %s", crowdgpu_last_error());
    const crowdgpu_character two[2] = {walker, walker};
    EXPECT(crowdgpu_crowd_spawn_batch(crowd, two, 2, batch) == CROWDGPU_ERROR_CAPACITY_EXCEEDED &&
               crowdgpu_crowd_live_count(crowd) == 3,
           "a batch past the capacity changes nothing: %s", crowdgpu_last_error());

    /* Remove: the handle goes stale; a batch with a stale or repeated handle is refused whole. */
    EXPECT(crowdgpu_crowd_remove(crowd, third) == CROWDGPU_OK && !crowdgpu_crowd_alive(crowd, third), "remove");
    EXPECT(crowdgpu_crowd_remove(crowd, third) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               strstr(crowdgpu_last_error(), "removed") != NULL,
           "a stale handle: %s", crowdgpu_last_error());
    crowdgpu_handle first = {0, 0};
    EXPECT(crowdgpu_crowd_handle(crowd, 0, &first) == CROWDGPU_OK && first.generation == 1, "handle of slot 0");
    const crowdgpu_handle twice[2] = {first, first};
    EXPECT(crowdgpu_crowd_remove_batch(crowd, twice, 2) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               strstr(crowdgpu_last_error(), "twice") != NULL && crowdgpu_crowd_alive(crowd, first),
           "a handle given twice: %s", crowdgpu_last_error());
    const crowdgpu_handle with_stale[2] = {first, third};
    EXPECT(crowdgpu_crowd_remove_batch(crowd, with_stale, 2) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               crowdgpu_crowd_alive(crowd, first),
           "a batch with a stale handle removes nobody: %s", crowdgpu_last_error());
    /* The freed slot is reused under a new generation; the old handle stays stale. */
    EXPECT(crowdgpu_crowd_spawn_batch(crowd, two, 1, batch) == CROWDGPU_OK && batch[0].slot == 2 &&
               batch[0].generation == 2 && !crowdgpu_crowd_alive(crowd, third),
           "the slot reused: slot %u generation %u", batch[0].slot, batch[0].generation);

    /* Samples: applied, late (ignored and counted), or the whole batch refused naming the sample. */
    crowdgpu_handle driven = {0, 0};
    EXPECT(crowdgpu_crowd_handle(crowd, 1, &driven) == CROWDGPU_OK, "handle of slot 1");
    const double times[2] = {0.1, 0.2};
    const float xs[2] = {2.0f, 2.3f}, zs[2] = {0.0f, 0.0f};
    uint32_t applied = 0, late = 0;
    const crowdgpu_handle both[2] = {driven, driven};
    EXPECT(crowdgpu_crowd_drive(crowd, both, times, xs, zs, NULL, 2, &applied, &late) == CROWDGPU_OK && applied == 2 &&
               late == 0,
           "two samples: applied %u late %u: %s", applied, late, crowdgpu_last_error());
    EXPECT(crowdgpu_crowd_drive(crowd, both, times, xs, zs, NULL, 1, &applied, &late) == CROWDGPU_OK && applied == 0 &&
               late == 1,
           "an old sample is late, not an error: applied %u late %u", applied, late);
    const float nan_x[1] = {NAN};
    const double later[1] = {0.3};
    EXPECT(crowdgpu_crowd_drive(crowd, both, later, nan_x, zs, NULL, 1, NULL, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               strstr(crowdgpu_last_error(), "sample 0") != NULL,
           "a NaN position: %s", crowdgpu_last_error());
    const crowdgpu_handle stale_and_good[2] = {third, driven};
    const double times2[2] = {0.3, 0.3};
    EXPECT(crowdgpu_crowd_drive(crowd, stale_and_good, times2, xs, zs, NULL, 2, NULL, NULL) ==
                   CROWDGPU_ERROR_INVALID_ARGUMENT &&
               crowdgpu_crowd_drive(crowd, both, later, xs, zs, NULL, 1, &applied, &late) == CROWDGPU_OK && applied == 1,
           "a stale handle refuses the whole batch (the good sample then applies alone): %s", crowdgpu_last_error());
    EXPECT(crowdgpu_crowd_set_driven_timing(crowd, -1.0, 0.5) == CROWDGPU_ERROR_INVALID_ARGUMENT, "a negative delay");

    /* Terrain: a tilted 2 x 2 grid, bilinear between its corners; bad ones refused, the ground kept. */
    const float heights[4] = {0.0f, 1.0f, 2.0f, 3.0f}; /* (x0,z0) (x1,z0) (x0,z1) (x1,z1) */
    const float origin[2] = {-5.0f, -5.0f}, size[2] = {10.0f, 10.0f}, no_size[2] = {0.0f, 10.0f};
    const float bad_heights[4] = {0.0f, NAN, 0.0f, 0.0f};
    EXPECT(crowdgpu_crowd_set_terrain(crowd, 2, 2, heights, origin, size) == CROWDGPU_OK, "terrain: %s",
           crowdgpu_last_error());
    EXPECT(fabsf(crowdgpu_crowd_ground_height(crowd, 0.0f, 0.0f) - 1.5f) < 1e-6f &&
               fabsf(crowdgpu_crowd_ground_height(crowd, 2.5f, -5.0f) - 0.75f) < 1e-6f &&
               fabsf(crowdgpu_crowd_ground_height(crowd, 99.0f, 99.0f) - 3.0f) < 1e-6f,
           "bilinear heights, the edge's beyond");
    EXPECT(crowdgpu_crowd_set_terrain(crowd, 2, 2, bad_heights, origin, size) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               crowdgpu_crowd_set_terrain(crowd, 2, 2, heights, origin, no_size) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               fabsf(crowdgpu_crowd_ground_height(crowd, 0.0f, 0.0f) - 1.5f) < 1e-6f,
           "a NaN height and a zero extent refused, the terrain kept: %s", crowdgpu_last_error());
    crowdgpu_crowd_destroy(crowd);

    /* A crowd made without driven keys (none driven, no keys asked for) refuses samples. */
    crowdgpu_crowd plain = NULL;
    EXPECT(crowdgpu_crowd_create_grid(&soldier, 1, 2, 1, CROWDGPU_IN_PLACE, &plain) == CROWDGPU_OK, "grid");
    crowdgpu_handle h0 = {0, 0};
    EXPECT(crowdgpu_crowd_handle(plain, 0, &h0) == CROWDGPU_OK &&
               crowdgpu_crowd_drive(plain, &h0, times, xs, zs, NULL, 1, NULL, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               strstr(crowdgpu_last_error(), "driven keys") != NULL,
           "samples for a crowd without keys: %s", crowdgpu_last_error());
    crowdgpu_crowd_destroy(plain);
    crowdgpu_model_destroy(soldier);
}

int main(void) {
    host_world_in_c();
    /* ---- Instance with validation and synchronization validation ---- */
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features_info = {VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features_info.enabledValidationFeatureCount = 1;
    features_info.pEnabledValidationFeatures = enables;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info = {VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.pNext = &features_info;
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = on_message;
    VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "c_api_smoke";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo instance_info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instance_info.pNext = &messenger_info;
    instance_info.pApplicationInfo = &app;
    instance_info.enabledLayerCount = 1;
    instance_info.ppEnabledLayerNames = &layer;
    instance_info.enabledExtensionCount = 1;
    instance_info.ppEnabledExtensionNames = &extension;
    VkInstance instance;
    VK_CHECK(vkCreateInstance(&instance_info, NULL, &instance));
    messenger_info.pNext = NULL;
    PFN_vkCreateDebugUtilsMessengerEXT create_messenger =
        (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT");
    VkDebugUtilsMessengerEXT messenger;
    VK_CHECK(create_messenger(instance, &messenger_info, NULL, &messenger));

    /* ---- A Vulkan 1.3 device with a graphics queue; crowdgpu's features enabled ---- */
    uint32_t count = 8;
    VkPhysicalDevice physicals[8];
    VkResult enumerated = vkEnumeratePhysicalDevices(instance, &count, physicals);
    if (enumerated != VK_SUCCESS && enumerated != VK_INCOMPLETE) return 1;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    uint32_t family = 0;
    for (uint32_t d = 0; d < count && !physical; ++d) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(physicals[d], &properties);
        if (properties.apiVersion < VK_API_VERSION_1_3) continue;
        uint32_t family_count = 16;
        VkQueueFamilyProperties families[16];
        vkGetPhysicalDeviceQueueFamilyProperties(physicals[d], &family_count, families);
        for (uint32_t f = 0; f < family_count; ++f)
            if ((families[f].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) ==
                (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) {
                physical = physicals[d], family = f;
                break;
            }
    }
    if (!physical) {
        fprintf(stderr, "no Vulkan 1.3 device\n");
        return 1;
    }
    VkPhysicalDeviceVulkan11Features vulkan11 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features vulkan12 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &vulkan11};
    VkPhysicalDeviceVulkan13Features vulkan13 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &vulkan12};
    VkPhysicalDeviceFeatures2 features = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan13};
    crowdgpu_enable_required_features(&features, &vulkan11, &vulkan12, &vulkan13);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.pNext = &features;
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    VkDevice device;
    VK_CHECK(vkCreateDevice(physical, &device_info, NULL, &device));
    VkQueue queue;
    vkGetDeviceQueue(device, family, 0, &queue);

    VkCommandPoolCreateInfo pool_info = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = family;
    VkCommandPool pool;
    VK_CHECK(vkCreateCommandPool(device, &pool_info, NULL, &pool));
    VkCommandBuffer commands[FRAMES_IN_FLIGHT];
    VkCommandBufferAllocateInfo allocate_info = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate_info.commandPool = pool;
    allocate_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate_info.commandBufferCount = FRAMES_IN_FLIGHT;
    VK_CHECK(vkAllocateCommandBuffers(device, &allocate_info, commands));
    VkFence fences[FRAMES_IN_FLIGHT];
    VkFenceCreateInfo fence_info = {VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    for (int i = 0; i < FRAMES_IN_FLIGHT; ++i) VK_CHECK(vkCreateFence(device, &fence_info, NULL, &fences[i]));

    /* ---- The crowd and the renderer through the C API ---- */
    crowdgpu_model soldier = NULL;
    EXPECT(crowdgpu_model_soldier(1, &soldier) == CROWDGPU_OK, "soldier: %s", crowdgpu_last_error());
    crowdgpu_crowd crowd = NULL;
    EXPECT(crowdgpu_crowd_create_grid(&soldier, 1, 16, 1, CROWDGPU_IN_PLACE, &crowd) == CROWDGPU_OK, "grid: %s",
           crowdgpu_last_error());
    const int32_t hand = crowdgpu_model_find_joint(soldier, "hand_r");
    EXPECT(hand >= 0 && crowdgpu_model_find_joint(soldier, "tail") == -1, "find_joint: hand_r %d", hand);
    /* The walk's footsteps: one per foot, named "footstep", at the feet, within the cycle. */
    const int32_t walk = crowdgpu_model_find_clip(soldier, "walk");
    uint32_t steps = 0;
    EXPECT(crowdgpu_model_event_count(soldier, (uint32_t)walk, &steps) == CROWDGPU_OK && steps == 2, "walk events %u: %s",
           steps, crowdgpu_last_error());
    const int32_t feet[2] = {crowdgpu_model_find_joint(soldier, "foot_l"), crowdgpu_model_find_joint(soldier, "foot_r")};
    int32_t step_joints[2] = {-1, -1};
    for (uint32_t e = 0; e < steps && e < 2; ++e) {
        const char* name = NULL;
        float seconds = -1.0f;
        EXPECT(crowdgpu_model_event_name(soldier, (uint32_t)walk, e, &name) == CROWDGPU_OK && name &&
                   strcmp(name, "footstep") == 0,
               "walk event %u named %s", e, name ? name : "(none)");
        EXPECT(crowdgpu_model_event_time(soldier, (uint32_t)walk, e, &seconds) == CROWDGPU_OK && seconds >= 0.0f &&
                   seconds <= 1.1f,
               "walk event %u at %f s", e, seconds);
        EXPECT(crowdgpu_model_event_joint(soldier, (uint32_t)walk, e, &step_joints[e]) == CROWDGPU_OK, "event joint: %s",
               crowdgpu_last_error());
    }
    EXPECT((step_joints[0] == feet[0] && step_joints[1] == feet[1]) || (step_joints[0] == feet[1] && step_joints[1] == feet[0]),
           "footsteps at joints %d and %d, feet %d and %d", step_joints[0], step_joints[1], feet[0], feet[1]);
    const char* no_name = NULL;
    EXPECT(crowdgpu_model_event_name(soldier, (uint32_t)walk, steps, &no_name) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               no_name == NULL && strlen(crowdgpu_last_error()) > 0,
           "an event past the last");
    EXPECT(crowdgpu_model_event_count(soldier, 99, &steps) == CROWDGPU_ERROR_INVALID_ARGUMENT, "events of clip 99");
    EXPECT(crowdgpu_model_event_count(NULL, 0, &steps) == CROWDGPU_ERROR_INVALID_ARGUMENT, "events of no model");
    crowdgpu_model_destroy(soldier); /* the crowd keeps its models */
    if (!crowd) return 1;
    EXPECT(crowdgpu_crowd_size(crowd) == 16, "crowd size %u", crowdgpu_crowd_size(crowd));
    /* A hand hangs between the soldier's knees and shoulders (the C++ tests compare it with the mesh). */
    float hand_rows[12];
    EXPECT(crowdgpu_crowd_joint_world(crowd, 0, (uint32_t)hand, 0.5, hand_rows) == CROWDGPU_OK, "joint_world: %s",
           crowdgpu_last_error());
    EXPECT(hand_rows[7] > 0.5f && hand_rows[7] < 1.5f, "hand at height %f", hand_rows[7]);
    EXPECT(crowdgpu_crowd_joint_world(crowd, 16, 0, 0.5, hand_rows) == CROWDGPU_ERROR_INVALID_ARGUMENT,
           "joint_world of a character the crowd lacks");

    /* Events of the whole crowd over two seconds: asked for the count first, then fetched; each
     * character's in time order within the window; one call is the two halves of the window. */
    EXPECT(crowdgpu_crowd_advance_to(crowd, 2.0) == CROWDGPU_OK, "advance: %s", crowdgpu_last_error());
    uint32_t everyone[16];
    for (uint32_t c = 0; c < 16; ++c) everyone[c] = c;
    uint32_t fired = 0, first_half = 0, second_half = 0;
    EXPECT(crowdgpu_crowd_events(crowd, everyone, 16, 0.0, 2.0, NULL, 0, &fired) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               fired > 16 * 2,
           "events counted: %u", fired);
    crowdgpu_event events[256], halves[256];
    EXPECT(fired <= 256 && crowdgpu_crowd_events(crowd, everyone, 16, 0.0, 2.0, events, 256, &fired) == CROWDGPU_OK,
           "events: %s", crowdgpu_last_error());
    EXPECT(crowdgpu_crowd_events(crowd, everyone, 16, 0.0, 1.0, halves, 256, &first_half) == CROWDGPU_OK &&
               crowdgpu_crowd_events(crowd, everyone, 16, 1.0, 2.0, halves + first_half, 256 - first_half,
                                     &second_half) == CROWDGPU_OK &&
               first_half + second_half == fired,
           "halves %u + %u of %u events", first_half, second_half, fired);
    for (uint32_t i = 0; i < fired && i < 256; ++i) {
        const crowdgpu_event* e = &events[i];
        EXPECT(e->character < 16 && e->clip == (uint32_t)walk && e->event < 2 && e->time > 0.0 && e->time <= 2.0,
               "event %u: character %u clip %u event %u at %f", i, e->character, e->clip, e->event, e->time);
        if (i > 0) {
            const crowdgpu_event* before = &events[i - 1];
            EXPECT(before->character < e->character || (before->character == e->character && before->time <= e->time),
                   "event %u out of order", i);
        }
        int found = 0; /* the same event in one of the halves */
        for (uint32_t k = 0; k < first_half + second_half && k < 256; ++k)
            found += halves[k].character == e->character && halves[k].event == e->event && halves[k].time == e->time;
        EXPECT(found == 1, "event %u found %d times in the halves", i, found);
    }
    uint32_t small = 0;
    EXPECT(crowdgpu_crowd_events(crowd, everyone, 16, 0.0, 2.0, events, 3, &small) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               small == fired && strstr(crowdgpu_last_error(), "room for 3") != NULL,
           "3 places for %u events: %s", small, crowdgpu_last_error());
    const uint32_t missing = 16;
    EXPECT(crowdgpu_crowd_events(crowd, &missing, 1, 0.0, 2.0, events, 256, &small) == CROWDGPU_ERROR_INVALID_ARGUMENT,
           "events of a character the crowd lacks");
    EXPECT(crowdgpu_crowd_events(crowd, everyone, 16, 0.0, 2.0, NULL, 256, &small) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
               crowdgpu_crowd_events(NULL, everyone, 16, 0.0, 2.0, events, 256, &small) == CROWDGPU_ERROR_INVALID_ARGUMENT,
           "events with NULLs");

    /* Arguments checked at the door (issue 41): non-finite times and characters on a milling crowd (were
     * SIGSEGVs), an unbounded event window (ran out of memory), a behaviour outside the enum (was an
     * in-place crowd), a NULL physical device (a SIGSEGV): each INVALID_ARGUMENT naming it. */
    {
        crowdgpu_model walker = NULL;
        EXPECT(crowdgpu_model_soldier(1, &walker) == CROWDGPU_OK, "soldier: %s", crowdgpu_last_error());
        crowdgpu_crowd mill = NULL;
        EXPECT(crowdgpu_crowd_create_grid(&walker, 1, 8, 1, CROWDGPU_MILL, &mill) == CROWDGPU_OK, "mill: %s",
               crowdgpu_last_error());
        float rows[12];
        EXPECT(crowdgpu_crowd_advance_to(mill, INFINITY) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "advanceTo: time") != NULL,
               "advance_to(inf): %s", crowdgpu_last_error());
        EXPECT(crowdgpu_crowd_advance_to(mill, NAN) == CROWDGPU_ERROR_INVALID_ARGUMENT, "advance_to(nan)");
        EXPECT(crowdgpu_crowd_joint_world(mill, 0, 0, INFINITY, rows) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   crowdgpu_crowd_joint_world(mill, 0, 0, 1e300, rows) == CROWDGPU_ERROR_INVALID_ARGUMENT,
               "joint_world at inf and 1e300: %s", crowdgpu_last_error());
        crowdgpu_character bad_phase = {0, 0, NAN, 1.0f, {0.0f, 0.0f, 0.0f}, 0.0f, 1.0f, {1.0f, 1.0f, 1.0f}};
        EXPECT(crowdgpu_crowd_spawn(mill, &bad_phase, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "phase") != NULL,
               "spawn with a NaN phase: %s", crowdgpu_last_error());
        bad_phase.phase = INFINITY;
        EXPECT(crowdgpu_crowd_spawn(mill, &bad_phase, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT, "spawn with an inf phase");
        EXPECT(crowdgpu_crowd_move_to(mill, 0, NAN, 0.0f, 1.0) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   crowdgpu_crowd_play(mill, 0, 0, 1.0, NAN) == CROWDGPU_ERROR_INVALID_ARGUMENT,
               "move_to a NaN x, play with a NaN fade");
        uint32_t counted = 0;
        EXPECT(crowdgpu_crowd_events(mill, everyone, 8, 0.0, INFINITY, NULL, 0, &counted) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "events: to") != NULL,
               "events to inf: %s", crowdgpu_last_error());
        EXPECT(crowdgpu_crowd_events(mill, everyone, 8, 0.0, 1e6, NULL, 0, &counted) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "longer than") != NULL,
               "events over 1e6 s: %s", crowdgpu_last_error());
        EXPECT(crowdgpu_crowd_size(mill) == 8 && crowdgpu_crowd_advance_to(mill, 30.0) == CROWDGPU_OK &&
                   crowdgpu_crowd_joint_world(mill, 7, 0, 30.0, rows) == CROWDGPU_OK && isfinite(rows[3]),
               "the milling crowd after the refusals: %s", crowdgpu_last_error());
        crowdgpu_crowd_destroy(mill);
        crowdgpu_crowd other = NULL;
        EXPECT(crowdgpu_crowd_create_grid(&walker, 1, 4, 1, (crowdgpu_behaviour)99, &other) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   other == NULL && strstr(crowdgpu_last_error(), "behaviour 99") != NULL,
               "behaviour 99: %s", crowdgpu_last_error());
        crowdgpu_model_destroy(walker);
    }

    crowdgpu_renderer_settings settings;
    crowdgpu_renderer_settings_default(&settings);
    EXPECT(crowdgpu_memory_needed(VK_NULL_HANDLE, crowd, &settings) == 0 &&
               strstr(crowdgpu_last_error(), "no physical device") != NULL,
           "memory_needed without a physical device: %s", crowdgpu_last_error());
    EXPECT(settings.color_format == VK_FORMAT_R8G8B8A8_SRGB && settings.depth_format == VK_FORMAT_D32_SFLOAT,
           "default formats %d, %d", settings.color_format, settings.depth_format);
    EXPECT(settings.raster == CROWDGPU_RASTER_AUTO && settings.mesh_raster_limit == -1.0f && settings.shadow_lod &&
               settings.shadow_raster_compute && settings.impostor_blend && settings.lod_fade && settings.events &&
               settings.event_capacity == 65536 && settings.shadow_cascades == 1 && settings.far_crowd,
           "default raster %d, mesh raster limit %g, shadow LOD %d, shadow raster compute %d, impostor blend %d, "
           "fades %d, events %d (%u), shadow cascades %u, far crowd %d", settings.raster, settings.mesh_raster_limit,
           settings.shadow_lod, settings.shadow_raster_compute, settings.impostor_blend, settings.lod_fade,
           settings.events, settings.event_capacity, settings.shadow_cascades, settings.far_crowd);
    settings.frames_in_flight = FRAMES_IN_FLIGHT;
    const crowdgpu_device lent = {instance, physical, device, family, &features};

    /* The settings the C++ API checks reach it: each bad one refused in one line naming it. */
    {
        crowdgpu_renderer refused = NULL;
        crowdgpu_renderer_settings bad = settings;
        bad.raster = (crowdgpu_raster)7;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "raster mode 7") != NULL && refused == NULL,
               "raster 7: %s", crowdgpu_last_error());
        bad = settings;
        bad.method = (crowdgpu_method)99;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "method 99") != NULL && refused == NULL,
               "method 99: %s", crowdgpu_last_error());
        bad = settings;
        const unsigned char two = 2; /* a bool a C host wrote as bytes */
        memcpy(&bad.shadows, &two, 1);
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "shadows: 2") != NULL,
               "shadows 2: %s", crowdgpu_last_error());
        bad = settings;
        bad.color_format = (VkFormat)0x7fffffff; /* no format: refused before the driver sees it */
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "not a Vulkan 1.3 format") != NULL,
               "colour format 0x7fffffff: %s", crowdgpu_last_error());
        bad = settings;
        bad.color_format = VK_FORMAT_D32_SFLOAT; /* a depth format as colour */
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_UNSUPPORTED,
               "D32 as colour: %s", crowdgpu_last_error());
        bad = settings;
        bad.mesh_raster_limit = -5.0f;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "mesh raster limit") != NULL,
               "mesh raster limit -5: %s", crowdgpu_last_error());
        bad = settings;
        bad.event_capacity = 0;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "event capacity") != NULL,
               "event capacity 0: %s", crowdgpu_last_error());
        bad = settings;
        bad.shadow_cascades = 5;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "shadow cascades") != NULL,
               "shadow cascades 5: %s", crowdgpu_last_error());
        bad = settings;
        bad.shadow_cascades = 4;
        bad.shadow_map_size = 32;
        EXPECT(crowdgpu_renderer_create(&lent, crowd, &bad, &refused) == CROWDGPU_ERROR_INVALID_ARGUMENT &&
                   strstr(crowdgpu_last_error(), "at least 64 texels") != NULL,
               "4 cascades in a 32-texel map: %s", crowdgpu_last_error());
    }

    /* A NULL argument: INVALID_ARGUMENT and a message. */
    crowdgpu_renderer renderer = NULL;
    EXPECT(crowdgpu_renderer_create(NULL, crowd, &settings, &renderer) == CROWDGPU_ERROR_INVALID_ARGUMENT,
           "create with a NULL device");
    EXPECT(strlen(crowdgpu_last_error()) > 0, "no message for a NULL device");
    EXPECT(crowdgpu_renderer_record_compute(NULL, commands[0], 0, NULL, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT,
           "record_compute with NULLs");
    EXPECT(crowdgpu_model_soldier(1, NULL) == CROWDGPU_ERROR_INVALID_ARGUMENT, "soldier with NULL out");

    EXPECT(crowdgpu_renderer_create(&lent, crowd, &settings, &renderer) == CROWDGPU_OK, "create: %s",
           crowdgpu_last_error());
    if (!renderer) return 1;

    /* Out of order: characters before this slot's compute. Nothing is recorded when a call fails. */
    EXPECT(crowdgpu_renderer_record_characters(renderer, commands[0], 0) == CROWDGPU_ERROR_WRONG_ORDER,
           "record_characters before record_compute");
    EXPECT(strlen(crowdgpu_last_error()) > 0, "no message for the wrong order");
    printf("wrong order: %s\n", crowdgpu_last_error());
    VkExtent2D filterExtent = {64, 64};
    EXPECT(crowdgpu_renderer_record_edge_filter(renderer, commands[0], 0, VK_NULL_HANDLE, VK_NULL_HANDLE,
                                                filterExtent) == CROWDGPU_ERROR_WRONG_ORDER,
           "record_edge_filter without the edge_filter setting");

    /* Setup: recorded, submitted, waited for. */
    VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands[0], &begin));
    EXPECT(crowdgpu_renderer_record_setup(renderer, commands[0]) == CROWDGPU_OK, "setup: %s", crowdgpu_last_error());
    VK_CHECK(vkEndCommandBuffer(commands[0]));
    VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands[0];
    VK_CHECK(vkResetFences(device, 1, &fences[0]));
    VK_CHECK(vkQueueSubmit(queue, 1, &submit, fences[0]));
    VK_CHECK(vkWaitForFences(device, 1, &fences[0], VK_TRUE, UINT64_MAX));
    crowdgpu_renderer_setup_completed(renderer);

    /* ---- The host's offscreen target in the library's default formats ---- */
    VkDeviceMemory color_memory, depth_memory;
    VkImageView color_view, depth_view;
    VkImage color = create_image(physical, device, settings.color_format,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_IMAGE_ASPECT_COLOR_BIT, &color_memory, &color_view);
    VkImage depth = create_image(physical, device, settings.depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                 VK_IMAGE_ASPECT_DEPTH_BIT, &depth_memory, &depth_view);
    VkBufferCreateInfo buffer_info = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    buffer_info.size = (VkDeviceSize)WIDTH * HEIGHT * 4;
    buffer_info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer readback;
    VK_CHECK(vkCreateBuffer(device, &buffer_info, NULL, &readback));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, readback, &requirements);
    VkMemoryAllocateInfo readback_allocate = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    readback_allocate.allocationSize = requirements.size;
    readback_allocate.memoryTypeIndex =
        memory_type(physical, requirements.memoryTypeBits,
                    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkDeviceMemory readback_memory;
    VK_CHECK(vkAllocateMemory(device, &readback_allocate, NULL, &readback_memory));
    VK_CHECK(vkBindBufferMemory(device, readback, readback_memory, 0));

    /* ---- Frames: two in flight, a fence per slot ---- */
    float center[3], radius, tallest;
    crowdgpu_crowd_bounds(crowd, center, &radius, &tallest);
    const float target[3] = {center[0], center[1] + 0.5f * tallest, center[2]};
    const float eye[3] = {center[0] + radius, center[1] + radius + tallest, center[2] + 2.0f * radius + 2.0f * tallest};
    const float sky[4] = {0.55f, 0.7f, 0.9f, 1.0f};
    const VkPipelineStageFlags2 fragment_tests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    for (uint32_t frame = 0; frame < FRAMES; ++frame) {
        const uint32_t slot = frame % FRAMES_IN_FLIGHT;
        const double time = (double)frame / 30.0;
        VK_CHECK(vkWaitForFences(device, 1, &fences[slot], VK_TRUE, UINT64_MAX));
        VK_CHECK(vkResetFences(device, 1, &fences[slot]));
        EXPECT(crowdgpu_crowd_advance_to(crowd, time) == CROWDGPU_OK, "advance: %s", crowdgpu_last_error());
        crowdgpu_frame_view view;
        crowdgpu_look_at(eye, target, 0.8f, 0.1f, 100.0f * radius, (VkExtent2D){WIDTH, HEIGHT}, time, &view);

        VkCommandBuffer cmd = commands[slot];
        VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
        EXPECT(crowdgpu_renderer_record_compute(renderer, cmd, slot, &view, crowd) == CROWDGPU_OK, "compute: %s",
               crowdgpu_last_error());
        EXPECT(crowdgpu_renderer_record_shadows(renderer, cmd, slot) == CROWDGPU_OK, "shadows: %s",
               crowdgpu_last_error());
        image_barrier(cmd, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
        image_barrier(cmd, depth, VK_IMAGE_ASPECT_DEPTH_BIT, fragment_tests,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, fragment_tests,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
        VkRenderingAttachmentInfo color_attachment = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color_attachment.imageView = color_view;
        color_attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        memcpy(color_attachment.clearValue.color.float32, sky, sizeof sky);
        VkRenderingAttachmentInfo depth_attachment = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth_attachment.imageView = depth_view;
        depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        depth_attachment.clearValue.depthStencil.depth = 1.0f;
        VkRenderingInfo rendering = {VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea.extent = (VkExtent2D){WIDTH, HEIGHT};
        rendering.layerCount = 1;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color_attachment;
        rendering.pDepthAttachment = &depth_attachment;
        vkCmdBeginRendering(cmd, &rendering);
        /* No ground: whatever is not sky in the image is the crowd. */
        EXPECT(crowdgpu_renderer_record_characters(renderer, cmd, slot) == CROWDGPU_OK, "characters: %s",
               crowdgpu_last_error());
        vkCmdEndRendering(cmd);
        if (frame == FRAMES - 1) {
            image_barrier(cmd, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
            VkBufferImageCopy region = {0};
            region.imageSubresource = (VkImageSubresourceLayers){VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = (VkExtent3D){WIDTH, HEIGHT, 1};
            vkCmdCopyImageToBuffer(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
            VkMemoryBarrier2 to_host = {VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
            to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
            to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
            to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
            VkDependencyInfo dependency = {VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dependency.memoryBarrierCount = 1;
            dependency.pMemoryBarriers = &to_host;
            vkCmdPipelineBarrier2(cmd, &dependency);
        }
        VK_CHECK(vkEndCommandBuffer(cmd));
        submit.pCommandBuffers = &cmd;
        VK_CHECK(vkQueueSubmit(queue, 1, &submit, fences[slot]));
    }
    VK_CHECK(vkWaitForFences(device, FRAMES_IN_FLIGHT, fences, VK_TRUE, UINT64_MAX));

    /* ---- The image: sky in a corner, the crowd (not sky) in the centre ---- */
    void* mapped;
    VK_CHECK(vkMapMemory(device, readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped));
    const uint8_t* rgba = mapped;
    const uint8_t* corner = rgba;
    EXPECT(corner[0] >= 190 && corner[0] <= 200 && corner[2] >= 238, "corner is not the sky: %u %u %u", corner[0],
           corner[1], corner[2]);
    uint32_t differing = 0, centre = 0;
    for (uint32_t y = HEIGHT / 4; y < 3 * HEIGHT / 4; ++y)
        for (uint32_t x = WIDTH / 4; x < 3 * WIDTH / 4; ++x, ++centre) {
            const uint8_t* p = rgba + 4 * (y * WIDTH + x);
            if (abs(p[0] - corner[0]) > 4 || abs(p[1] - corner[1]) > 4 || abs(p[2] - corner[2]) > 4) ++differing;
        }
    printf("centre: %u of %u pixels differ from the sky\n", differing, centre);
    EXPECT(differing >= centre / 20, "the centre is (almost) all sky: %u of %u pixels differ", differing, centre);
    vkUnmapMemory(device, readback_memory);

    /* ---- Tear down: renderer, crowd, then the host's objects ---- */
    crowdgpu_renderer_destroy(renderer);
    crowdgpu_crowd_destroy(crowd);
    vkDestroyBuffer(device, readback, NULL);
    vkFreeMemory(device, readback_memory, NULL);
    vkDestroyImageView(device, color_view, NULL);
    vkDestroyImage(device, color, NULL);
    vkFreeMemory(device, color_memory, NULL);
    vkDestroyImageView(device, depth_view, NULL);
    vkDestroyImage(device, depth, NULL);
    vkFreeMemory(device, depth_memory, NULL);
    for (int i = 0; i < FRAMES_IN_FLIGHT; ++i) vkDestroyFence(device, fences[i], NULL);
    vkDestroyCommandPool(device, pool, NULL);
    vkDestroyDevice(device, NULL);
    PFN_vkDestroyDebugUtilsMessengerEXT destroy_messenger =
        (PFN_vkDestroyDebugUtilsMessengerEXT)vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT");
    destroy_messenger(instance, messenger, NULL);
    vkDestroyInstance(instance, NULL);

    EXPECT(validation_messages == 0, "the validation layer reported %d message(s)", validation_messages);
    if (failures) fprintf(stderr, "c_api_smoke: %d check(s) failed\n", failures);
    else printf("c_api_smoke: OK\n");
    return failures ? 1 : 0;
}
