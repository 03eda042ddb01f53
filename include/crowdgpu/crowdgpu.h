/* crowdgpu: the C API (C11), for hosts in C and for bindings (C#, Rust, Python).
 *
 * The same library as the C++ headers, in the few calls a host needs: load a model, build a crowd,
 * spawn and command characters, create a renderer on the host's device, record, destroy. Every
 * call that can fail returns a crowdgpu_result; crowdgpu_last_error() then gives a one-line message
 * (per thread, valid until the thread's next failing call). Handles are opaque; destroy what you
 * create, renderers before their crowd, and both before the host destroys its device. The record
 * contract is renderer.hpp's: recordSetup once (submit it before the first frame), then per frame
 * slot recordCompute, recordShadows (outside any pass), recordGround and recordCharacters (inside
 * the host's dynamic-rendering colour pass). Link crowdgpu::renderer (CMake) or crowdgpu (pkg-config). */
#ifndef CROWDGPU_H
#define CROWDGPU_H

#include <stdbool.h>
#include <stdint.h>

#include <vulkan/vulkan.h>

#include "crowdgpu/version.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum crowdgpu_result {
    CROWDGPU_OK = 0,
    CROWDGPU_ERROR_INVALID_ARGUMENT = 1,
    CROWDGPU_ERROR_UNSUPPORTED = 2,
    CROWDGPU_ERROR_OUT_OF_DEVICE_MEMORY = 3,
    CROWDGPU_ERROR_OUT_OF_HOST_MEMORY = 4,
    CROWDGPU_ERROR_WRONG_ORDER = 5,
    CROWDGPU_ERROR_LOAD_FAILED = 6,
    CROWDGPU_ERROR_VULKAN = 7,
    CROWDGPU_ERROR_CAPACITY_EXCEEDED = 8
} crowdgpu_result;

/* The message of this thread's last failure ("" if none). */
const char* crowdgpu_last_error(void);

typedef struct crowdgpu_model_t* crowdgpu_model;
typedef struct crowdgpu_crowd_t* crowdgpu_crowd;
typedef struct crowdgpu_renderer_t* crowdgpu_renderer;

/* ---- Models (Vulkan-free) ---- */
crowdgpu_result crowdgpu_model_soldier(uint32_t seed, crowdgpu_model* out);
crowdgpu_result crowdgpu_model_horse(uint32_t seed, crowdgpu_model* out);
/* The soldier on the horse (crowdgpu::Model::cavalry). */
crowdgpu_result crowdgpu_model_cavalry(uint32_t seed, crowdgpu_model* out);
/* `rider` seated on `mount`'s joint `saddle_joint` (NULL: "saddle") as one model (Model::mounted);
   CROWDGPU_ERROR_INVALID_ARGUMENT naming the mount and joint when the mount has no such joint. */
crowdgpu_result crowdgpu_model_mounted(crowdgpu_model mount, crowdgpu_model rider, const char* saddle_joint,
                                       crowdgpu_model* out);
/* asset_root may be NULL (the file's own folder). */
crowdgpu_result crowdgpu_model_load_gltf(const char* path, const char* asset_root, crowdgpu_model* out);
/* The clip of this name, or -1. */
int32_t crowdgpu_model_find_clip(crowdgpu_model model, const char* name);
uint32_t crowdgpu_model_clip_count(crowdgpu_model model);
/* The joint of this name (the soldier's "hand_r", a glTF node's name), or -1. */
int32_t crowdgpu_model_find_joint(crowdgpu_model model, const char* name);
/* A new model: `model` carrying a built-in prop, "rifle" or "flag", on the joint named `joint` (docs/props.md).
 * offset: the prop's space to the joint's, three rows of a 3x4 matrix [R*s | t] (NULL: identity); share:
 * of the characters that carry it (0..1; C characters and grids choose by share and seed). Fails with
 * CROWDGPU_ERROR_INVALID_ARGUMENT naming the model and the joint when the model has no such joint. */
crowdgpu_result crowdgpu_model_with_prop(crowdgpu_model model, const char* prop, const char* joint,
                                         const float offset[12], float share, crowdgpu_model* out);
/* The same with the first mesh of a glTF 2.0 file (.gltf or .glb) as the prop (crowdgpu::Prop::fromGltf:
 * rigid, base-colour factors, its own levels of detail). asset_root: the folder external buffers must lie
 * in (NULL: the file's own). A file that cannot be used fails with CROWDGPU_ERROR_LOAD_FAILED and one line
 * naming the file and the problem in crowdgpu_last_error(). */
crowdgpu_result crowdgpu_model_with_gltf_prop(crowdgpu_model model, const char* path, const char* asset_root,
                                              const char* joint, const float offset[12], float share,
                                              crowdgpu_model* out);
/* A clip's animation events, in time order (crowdgpu::Model::eventCount, eventName, eventTime,
 * eventJoint): a "footstep" per foot touchdown on the built-in models' walking clips, a glTF
 * animation's from its extras (docs/events.md). A model, clip or event that does not exist is
 * CROWDGPU_ERROR_INVALID_ARGUMENT, with nothing written. The name lives as long as the model. */
crowdgpu_result crowdgpu_model_event_count(crowdgpu_model model, uint32_t clip, uint32_t* count);
crowdgpu_result crowdgpu_model_event_name(crowdgpu_model model, uint32_t clip, uint32_t event, const char** name);
crowdgpu_result crowdgpu_model_event_time(crowdgpu_model model, uint32_t clip, uint32_t event, float* seconds);
/* The joint where the event happens (a footstep's foot), or -1 for none. */
crowdgpu_result crowdgpu_model_event_joint(crowdgpu_model model, uint32_t clip, uint32_t event, int32_t* joint);
void crowdgpu_model_destroy(crowdgpu_model model);

/* ---- Crowds (Vulkan-free) ---- */
typedef enum crowdgpu_behaviour { CROWDGPU_IN_PLACE = 0, CROWDGPU_MARCH = 1, CROWDGPU_MILL = 2 } crowdgpu_behaviour;

/* Who moves a character (crowdgpu::MotionSource): the crowd's behaviour, the host's samples from its
 * memory (crowdgpu_crowd_drive), or from a device buffer (crowdgpu_renderer_record_compute_samples). */
typedef enum crowdgpu_motion {
    CROWDGPU_MOTION_BEHAVIOUR = 0,
    CROWDGPU_MOTION_HOST_SAMPLES = 1,
    CROWDGPU_MOTION_DEVICE_SAMPLES = 2
} crowdgpu_motion;

typedef struct crowdgpu_character {
    uint32_t model, clip;
    float phase, speed;
    float position[3];
    float heading, scale;
    float tint[3];
    crowdgpu_motion motion;
} crowdgpu_character;

/* The most characters of each model at once (per_model, model_count entries; NULL: the initial ones), and
 * the keys a slot keeps for driven characters (crowdgpu::CrowdCapacity; 8 covers 50 Hz samples at a
 * 0.1 s delay; 0: 8 when any initial character is driven, else none). */
typedef struct crowdgpu_capacity {
    const uint32_t* per_model;
    uint32_t driven_keys;
} crowdgpu_capacity;

/* A grid of `count` characters of the models (equal shares), each playing its model's "walk" (or
 * first) clip with seeded jitter. The crowd keeps its models alive: the caller may destroy its own
 * handles afterwards. */
crowdgpu_result crowdgpu_crowd_create_grid(const crowdgpu_model* models, uint32_t model_count, uint32_t count,
                                           uint32_t seed, crowdgpu_behaviour behaviour, crowdgpu_crowd* out);
/* A character of a crowd whose population changes (crowdgpu::CharacterHandle): its slot, the index the
 * per-character calls take, and the slot's generation; stale once the character is removed. */
typedef struct crowdgpu_handle {
    uint32_t slot, generation;
} crowdgpu_handle;
/* A crowd of `count` characters (slots 0 .. count-1) of the models, and room for more (`capacity`, NULL:
 * none beyond them, 8 driven keys a slot); each model's spare slots follow the characters. characters may
 * be NULL when count is 0. */
crowdgpu_result crowdgpu_crowd_create(const crowdgpu_model* models, uint32_t model_count,
                                      const crowdgpu_character* characters, uint32_t count,
                                      const crowdgpu_capacity* capacity, uint32_t seed, crowdgpu_behaviour behaviour,
                                      crowdgpu_crowd* out);
/* Adds a character in a free slot of its model (crowdgpu::Crowd::spawn); *handle (may be NULL) names it.
 * CROWDGPU_ERROR_CAPACITY_EXCEEDED when every slot of its model is taken; nothing changes then. */
crowdgpu_result crowdgpu_crowd_spawn(crowdgpu_crowd crowd, const crowdgpu_character* character, crowdgpu_handle* handle);
/* The character leaves; its slot is free. A stale handle is CROWDGPU_ERROR_INVALID_ARGUMENT. */
crowdgpu_result crowdgpu_crowd_remove(crowdgpu_crowd crowd, crowdgpu_handle handle);
/* Batches (crowdgpu::Crowd::spawn and remove over arrays): all or none, as the C++ calls. handles[i]
 * names characters[i]. */
crowdgpu_result crowdgpu_crowd_spawn_batch(crowdgpu_crowd crowd, const crowdgpu_character* characters, size_t count,
                                           crowdgpu_handle* handles);
crowdgpu_result crowdgpu_crowd_remove_batch(crowdgpu_crowd crowd, const crowdgpu_handle* handles, size_t count);
/* Whether the handle names a living character (false for a NULL crowd). */
bool crowdgpu_crowd_alive(crowdgpu_crowd crowd, crowdgpu_handle handle);
/* The handle of slot `slot`'s living character; a free slot is CROWDGPU_ERROR_INVALID_ARGUMENT. */
crowdgpu_result crowdgpu_crowd_handle(crowdgpu_crowd crowd, uint32_t slot, crowdgpu_handle* handle);
/* The living characters (crowdgpu_crowd_size counts the slots). */
uint32_t crowdgpu_crowd_live_count(crowdgpu_crowd crowd);
/* The host's samples for `count` characters (crowdgpu::Crowd::drive): characters[i] at (x[i], z[i])
 * metres at times[i] scene seconds, facing headings[i] radians (headings may be NULL; NaN: towards the
 * motion). The whole batch is refused, nothing applied, naming the first bad sample; a sample no later than
 * its character's newest is ignored and counted in *late. applied and late may be NULL. */
crowdgpu_result crowdgpu_crowd_drive(crowdgpu_crowd crowd, const crowdgpu_handle* characters, const double* times,
                                     const float* x, const float* z, const float* headings, uint32_t count,
                                     uint32_t* applied, uint32_t* late);
/* How driven characters are drawn (crowdgpu::DrivenTiming): `delay` seconds behind their samples, going on
 * for at most `extrapolate` seconds past the newest (0 to 3,600 s each). */
crowdgpu_result crowdgpu_crowd_set_driven_timing(crowdgpu_crowd crowd, double delay, double extrapolate);
/* A model's gait bands for driven characters (crowdgpu::GaitSettings). */
typedef struct crowdgpu_gait_settings {
    float walk_from, run_from, hysteresis, fade, turn_rate, turn_speed;
} crowdgpu_gait_settings;
crowdgpu_result crowdgpu_crowd_gait_settings(crowdgpu_crowd crowd, uint32_t model, crowdgpu_gait_settings* out);
crowdgpu_result crowdgpu_crowd_set_gait_settings(crowdgpu_crowd crowd, uint32_t model,
                                                 const crowdgpu_gait_settings* settings);
/* The ground every character stands on (crowdgpu::Crowd::setTerrain): columns x rows heights (metres,
 * row-major, x fastest) over the rectangle from origin (x, z) of size (width, depth); 0 x 0: flat again. */
crowdgpu_result crowdgpu_crowd_set_terrain(crowdgpu_crowd crowd, uint32_t columns, uint32_t rows, const float* heights,
                                           const float origin[2], const float size[2]);
/* The ground's height at (x, z). */
float crowdgpu_crowd_ground_height(crowdgpu_crowd crowd, float x, float z);
/* The ground the crowd may cover (crowdgpu::Crowd::setWorldBounds): shadows are fitted to it. */
crowdgpu_result crowdgpu_crowd_set_world_bounds(crowdgpu_crowd crowd, const float lo[3], const float hi[3]);
crowdgpu_result crowdgpu_crowd_move_to(crowdgpu_crowd crowd, uint32_t character, float x, float z, double at);
crowdgpu_result crowdgpu_crowd_play(crowdgpu_crowd crowd, uint32_t character, int32_t clip, double at, float fade);
/* Plans every character up to `time` seconds: once per frame, before recording. Scene times are
 * doubles: a crowd is as exact at 1e9 s as at 0 s. Every call refuses a time that is not finite or lies
 * outside +-1e10 s (crowdgpu::kLargestTime), and any NaN, infinite or out-of-range position, speed,
 * phase, heading, scale, tint, rate, fade or enum value, with CROWDGPU_ERROR_INVALID_ARGUMENT naming it
 * (docs/embedding.md, "Argument ranges"). */
crowdgpu_result crowdgpu_crowd_advance_to(crowdgpu_crowd crowd, double time);
/* The slots, living or free (crowdgpu::Crowd::size). */
uint32_t crowdgpu_crowd_size(crowdgpu_crowd crowd);
/* The CPU threads the library's parallel work shares, the calling thread's included (0: one per core,
 * the default; 1: all on the caller's thread; at most 1024): crowdgpu::setWorkerThreads. Before any
 * crowd work, or while no thread uses a crowd. */
crowdgpu_result crowdgpu_set_worker_threads(uint32_t threads);
uint32_t crowdgpu_worker_threads(void);
/* Joint `joint` of `character` in world space at `time`: 12 floats, the rows of a 3x4 matrix, its
 * last column the joint's position (crowdgpu::Crowd::jointWorld: exact with what the renderer draws;
 * times from one replan back on). About 50 ns a joint of the character's model. */
crowdgpu_result crowdgpu_crowd_joint_world(crowdgpu_crowd crowd, uint32_t character, uint32_t joint, double time,
                                           float out[12]);
/* An event a character fired: event `event` of its model's clip `clip` at scene time `time`. */
typedef struct crowdgpu_event {
    uint32_t character, clip, event;
    double time;
} crowdgpu_event;
/* The events that `character_count` characters fire at times from < t <= to (crowdgpu::Crowd::events:
 * by character in the order given, each in time order; exact, the same split over any frames). Sets
 * *count to how many fired and writes them to out[0 .. *count) when they fit in `capacity`; when
 * they do not, writes none and returns CROWDGPU_ERROR_INVALID_ARGUMENT (call again with room for
 * *count; capacity 0 and out NULL asks for the count alone, which stores no event). A character that
 * does not exist, a window before what the crowd still knows or longer than 3,600 s
 * (crowdgpu::kLargestEventWindow) is CROWDGPU_ERROR_INVALID_ARGUMENT. About 100 ns a character for a
 * frame's window; memory: at most `capacity` events, none kept after the call past 1.5 MiB. */
crowdgpu_result crowdgpu_crowd_events(crowdgpu_crowd crowd, const uint32_t* characters, uint32_t character_count,
                                      double from, double to, crowdgpu_event* out, uint32_t capacity, uint32_t* count);
void crowdgpu_crowd_bounds(crowdgpu_crowd crowd, float center[3], float* radius, float* tallest);
void crowdgpu_crowd_destroy(crowdgpu_crowd crowd);

/* ---- The renderer on the host's device ---- */
/* Sets the features crowdgpu needs in the host's chain for vkCreateDevice (Vulkan 1.3). */
void crowdgpu_enable_required_features(VkPhysicalDeviceFeatures2* features, VkPhysicalDeviceVulkan11Features* vulkan11,
                                       VkPhysicalDeviceVulkan12Features* vulkan12,
                                       VkPhysicalDeviceVulkan13Features* vulkan13);

typedef struct crowdgpu_device {
    VkInstance instance;
    VkPhysicalDevice physical_device;
    VkDevice device;
    uint32_t queue_family;
    const VkPhysicalDeviceFeatures2* enabled_features; /* the chain the device was created with */
} crowdgpu_device;

typedef enum crowdgpu_method {
    CROWDGPU_TWO_PASS = 0,
    CROWDGPU_TWO_PASS_DIRECT = 1,
    CROWDGPU_VERTEX_SHADER = 2,
    CROWDGPU_VERTEX_SHADER_INSTANCED = 3,
    CROWDGPU_COMPUTE = 4,
    CROWDGPU_STATIC = 5
} crowdgpu_method;

/* Which rasterizer draws impostors and small characters' meshes (crowdgpu::Raster, docs/compute-raster.md). */
typedef enum crowdgpu_raster {
    CROWDGPU_RASTER_HARDWARE = 0,
    CROWDGPU_RASTER_COMPUTE = 1,
    CROWDGPU_RASTER_AUTO = 2
} crowdgpu_raster;

/* Each field as crowdgpu::RendererSettings' of the same name (include/crowdgpu/renderer.hpp). */
typedef struct crowdgpu_renderer_settings {
    VkFormat color_format, depth_format;
    VkSampleCountFlagBits samples;
    crowdgpu_method method;
    bool gpu_animation, lod, impostors, shadows;
    float impostor_threshold;
    uint32_t mesh_capacity, shadow_map_size, frames_in_flight;
    crowdgpu_raster raster;
    float mesh_raster_limit;   /* -1: automatic; 0: meshes never in compute; > 0: that many pixels */
    bool shadow_lod;           /* casters at a level from their size in the shadow map */
    bool shadow_raster_compute; /* the shadow map's casters rasterized in compute (else hardware) */
    bool impostor_blend;       /* impostors blend views, bands and frames (else the nearest cell) */
    bool lod_fade;             /* level changes fade over a band: mesh levels morph, impostors dither (else switch at once) */
    bool events;               /* animation events of the characters in view, in the frame's output */
    uint32_t event_capacity;
    uint32_t shadow_cascades;  /* 1 to 4: the shadow map's cascades, split by distance */
    bool far_crowd;            /* impostors of 16 px or less averaged by coverage (else cut at half coverage) */
    bool ground;               /* record_characters draws the checkered ground behind the characters */
    bool sky;                  /* and then kHorizonColor on every pixel left at the cleared depth: the host
                                  need not clear its colour attachment (loadOp DONT_CARE) */
    bool edge_filter;          /* record_edge_filter anti-aliases the finished picture in compute */
    uint32_t terrain_samples;  /* room for a terrain of this many heights set later (0: the crowd's own) */
} crowdgpu_renderer_settings;

/* The C++ defaults: R8G8B8A8_SRGB, D32_SFLOAT, 1 sample, two-pass, GPU animation, LOD, shadows (casters
   at their shadow level, rasterized in compute), raster auto, impostor blend, fades, events, the far crowd
   averaged; no ground, no sky, no edge filter. */
void crowdgpu_renderer_settings_default(crowdgpu_renderer_settings* settings);

typedef struct crowdgpu_frame_view {
    float view[16], projection[16]; /* column-major; projection in Vulkan clip space, depth 0..1 */
    VkRect2D viewport;
    double time; /* seconds on the crowd's clock */
} crowdgpu_frame_view;

void crowdgpu_look_at(const float eye[3], const float target[3], float vertical_fov, float near_plane, float far_plane,
                      VkExtent2D extent, double time, crowdgpu_frame_view* out);

/* Device bytes a renderer with these settings will allocate for the crowd (0 on failure, e.g. a NULL
   physical device; crowdgpu_last_error() says why). */
uint64_t crowdgpu_memory_needed(VkPhysicalDevice physical_device, crowdgpu_crowd crowd,
                                const crowdgpu_renderer_settings* settings);

crowdgpu_result crowdgpu_renderer_create(const crowdgpu_device* device, crowdgpu_crowd crowd,
                                         const crowdgpu_renderer_settings* settings, crowdgpu_renderer* out);
crowdgpu_result crowdgpu_renderer_record_setup(crowdgpu_renderer renderer, VkCommandBuffer cmd);
void crowdgpu_renderer_setup_completed(crowdgpu_renderer renderer);
/* `crowd`: the renderer's crowd, or one of the same layout (crowdgpu::Renderer::recordCompute). */
crowdgpu_result crowdgpu_renderer_record_compute(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot,
                                                 const crowdgpu_frame_view* view, crowdgpu_crowd crowd);
/* The host's device samples of a frame (crowdgpu::DeviceSamples): one crowdgpu_device_sample per slot. */
typedef struct crowdgpu_device_sample {
    float time, x, z, heading; /* time relative to the frame's (NaN: no sample); heading NaN: towards the motion */
} crowdgpu_device_sample;
typedef struct crowdgpu_device_samples {
    VkBuffer buffer;
    VkDeviceSize offset, size;
} crowdgpu_device_samples;
/* record_compute with the host's device samples for the crowd's device-driven characters. */
crowdgpu_result crowdgpu_renderer_record_compute_samples(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot,
                                                         const crowdgpu_frame_view* view, crowdgpu_crowd crowd,
                                                         const crowdgpu_device_samples* samples);
crowdgpu_result crowdgpu_renderer_record_shadows(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot);
crowdgpu_result crowdgpu_renderer_record_ground(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot);
crowdgpu_result crowdgpu_renderer_record_characters(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot);
/* After the colour pass, with edge_filter: `source` sampled, `destination` an R8G8B8A8_UNORM storage view
   (Renderer::recordEdgeFilter says the layouts and barriers). */
crowdgpu_result crowdgpu_renderer_record_edge_filter(crowdgpu_renderer renderer, VkCommandBuffer cmd, uint32_t slot,
                                                     VkImageView source, VkImageView destination, VkExtent2D extent);
void crowdgpu_renderer_destroy(crowdgpu_renderer renderer);

#ifdef __cplusplus
}
#endif

#endif
