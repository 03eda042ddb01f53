// The C API over the C++ one: handles own C++ objects; exceptions become result codes and a
// per-thread message.
#include "crowdgpu/crowdgpu.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "crowdgpu/crowd.hpp"
#include "crowdgpu/renderer.hpp"

struct crowdgpu_model_t {
    crowdgpu::Model model;
};
struct crowdgpu_crowd_t {
    crowdgpu::Crowd crowd;
};
struct crowdgpu_renderer_t {
    crowdgpu::Renderer renderer;
};

namespace {

thread_local std::string lastError;

// Runs `f`; a failure becomes its code and this thread's message.
template <class F>
crowdgpu_result guarded(F&& f) {
    try {
        f();
        return CROWDGPU_OK;
    } catch (const crowdgpu::Error& error) {
        lastError = error.what();
        return static_cast<crowdgpu_result>(error.code());
    } catch (const std::bad_alloc&) {
        lastError = "out of host memory";
        return CROWDGPU_ERROR_OUT_OF_HOST_MEMORY;
    } catch (const std::exception& error) {
        lastError = error.what();
        return CROWDGPU_ERROR_INVALID_ARGUMENT;
    }
}

crowdgpu_result invalid(const std::string& message) {
    lastError = message;
    return CROWDGPU_ERROR_INVALID_ARGUMENT;
}

// C enums and bools as the integers the host stored. Loading a value outside a C++ enum's or bool's
// range as that type is undefined behaviour (UBSan stops on it), and a C host can store any integer:
// each is read as its bytes, and is checked before it becomes a C++ value. The enums' ranges are the
// C++ API's checks (the C enums have the C++ enums' numbers); what only C can get wrong is checked here.
template <class T>
std::int64_t stored(const T& field) {
    static_assert(sizeof(T) == 1 || sizeof(T) == 4, "a C bool or enum");
    if constexpr (sizeof(T) == 1) {
        unsigned char byte;
        std::memcpy(&byte, &field, 1);
        return byte;
    } else {
        std::int32_t value;
        std::memcpy(&value, &field, 4);
        return value;
    }
}

bool boolOf(const char* name, const bool& field) {
    const std::int64_t value = stored(field);
    if (value > 1)
        throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument,
                              std::string("crowdgpu_renderer_settings.") + name + ": " + std::to_string(value) +
                                  " is not a bool (0 or 1)");
    return value == 1;
}

// A Vulkan enum (VkFormat, VkSampleCountFlagBits) holds 0 .. 0x7FFFFFFF; the C++ API checks the value.
template <class T>
T vulkanEnumOf(const char* name, const T& field) {
    const std::int64_t value = stored(field);
    if (value < 0)
        throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument, std::string("crowdgpu_renderer_settings.") + name +
                                                                        ": " + std::to_string(value) + " is negative");
    return static_cast<T>(value);
}

crowdgpu::RendererSettings settingsOf(const crowdgpu_renderer_settings& s) {
    crowdgpu::RendererSettings r;
    r.target = {vulkanEnumOf("color_format", s.color_format), vulkanEnumOf("depth_format", s.depth_format),
                vulkanEnumOf("samples", s.samples)};
    r.method = static_cast<crowdgpu::Method>(stored(s.method));
    r.animation = boolOf("gpu_animation", s.gpu_animation) ? crowdgpu::Animation::Gpu : crowdgpu::Animation::Cpu;
    r.lod = boolOf("lod", s.lod);
    r.impostors = boolOf("impostors", s.impostors);
    r.impostorThreshold = s.impostor_threshold;
    r.meshCapacity = s.mesh_capacity;
    r.shadows = boolOf("shadows", s.shadows);
    r.shadowMapSize = s.shadow_map_size;
    r.framesInFlight = s.frames_in_flight;
    r.raster = static_cast<crowdgpu::Raster>(stored(s.raster));
    r.meshRasterLimit = s.mesh_raster_limit;
    r.shadowLod = boolOf("shadow_lod", s.shadow_lod);
    r.shadowRaster = boolOf("shadow_raster_compute", s.shadow_raster_compute) ? crowdgpu::ShadowRaster::Compute
                                                                               : crowdgpu::ShadowRaster::Hardware;
    r.impostorBlend = boolOf("impostor_blend", s.impostor_blend);
    r.lodFade = boolOf("lod_fade", s.lod_fade);
    r.events = boolOf("events", s.events);
    r.eventCapacity = s.event_capacity;
    r.shadowCascades = s.shadow_cascades;
    r.farCrowd = boolOf("far_crowd", s.far_crowd);
    r.ground = boolOf("ground", s.ground);
    r.sky = boolOf("sky", s.sky);
    r.edgeFilter = boolOf("edge_filter", s.edge_filter);
    r.terrainSamples = s.terrain_samples;
    return r;
}

crowdgpu::Character characterOf(const crowdgpu_character& c) {
    crowdgpu::Character character;
    character.model = c.model, character.clip = c.clip, character.phase = c.phase, character.speed = c.speed;
    std::memcpy(character.position, c.position, sizeof character.position);
    character.heading = c.heading, character.scale = c.scale;
    std::memcpy(character.tint, c.tint, sizeof character.tint);
    if (c.motion < CROWDGPU_MOTION_BEHAVIOUR || c.motion > CROWDGPU_MOTION_DEVICE_SAMPLES)
        throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument,
                              "a character's motion is " + std::to_string(static_cast<int>(c.motion)) + ", not 0 to 2");
    character.motion = static_cast<crowdgpu::MotionSource>(c.motion);
    return character;
}

crowdgpu::FrameView viewOf(const crowdgpu_frame_view& v) {
    crowdgpu::FrameView result;
    std::memcpy(result.view, v.view, sizeof result.view);
    std::memcpy(result.projection, v.projection, sizeof result.projection);
    result.viewport = v.viewport;
    result.time = v.time;
    return result;
}

}  // namespace

extern "C" {

const char* crowdgpu_last_error(void) { return lastError.c_str(); }

crowdgpu_result crowdgpu_model_soldier(uint32_t seed, crowdgpu_model* out) {
    if (!out) return invalid("crowdgpu_model_soldier: out is NULL");
    return guarded([&] { *out = new crowdgpu_model_t{crowdgpu::Model::soldier(seed)}; });
}

crowdgpu_result crowdgpu_model_horse(uint32_t seed, crowdgpu_model* out) {
    if (!out) return invalid("crowdgpu_model_horse: out is NULL");
    return guarded([&] { *out = new crowdgpu_model_t{crowdgpu::Model::horse(seed)}; });
}

crowdgpu_result crowdgpu_model_cavalry(uint32_t seed, crowdgpu_model* out) {
    if (!out) return invalid("crowdgpu_model_cavalry: out is NULL");
    return guarded([&] { *out = new crowdgpu_model_t{crowdgpu::Model::cavalry(seed)}; });
}

crowdgpu_result crowdgpu_model_mounted(crowdgpu_model mount, crowdgpu_model rider, const char* saddle_joint,
                                       crowdgpu_model* out) {
    if (!mount || !rider || !out) return invalid("crowdgpu_model_mounted: mount, rider or out is NULL");
    return guarded([&] {
        *out = new crowdgpu_model_t{crowdgpu::Model::mounted(mount->model, rider->model,
                                                             saddle_joint ? saddle_joint : "saddle")};
    });
}

crowdgpu_result crowdgpu_model_load_gltf(const char* path, const char* asset_root, crowdgpu_model* out) {
    if (!out || !path) return invalid("crowdgpu_model_load_gltf: path or out is NULL");
    return guarded([&] { *out = new crowdgpu_model_t{crowdgpu::Model::fromGltf(path, asset_root ? asset_root : "")}; });
}

int32_t crowdgpu_model_find_clip(crowdgpu_model model, const char* name) {
    return model && name ? model->model.findClip(name) : -1;
}

int32_t crowdgpu_model_find_joint(crowdgpu_model model, const char* name) {
    return model && name ? model->model.findJoint(name) : -1;
}

uint32_t crowdgpu_model_clip_count(crowdgpu_model model) { return model ? model->model.clipCount() : 0; }

crowdgpu_result crowdgpu_model_event_count(crowdgpu_model model, uint32_t clip, uint32_t* count) {
    if (!model || !count) return invalid("crowdgpu_model_event_count: model or count is NULL");
    return guarded([&] { *count = model->model.eventCount(clip); });
}

crowdgpu_result crowdgpu_model_event_name(crowdgpu_model model, uint32_t clip, uint32_t event, const char** name) {
    if (!model || !name) return invalid("crowdgpu_model_event_name: model or name is NULL");
    return guarded([&] { *name = model->model.eventName(clip, event).c_str(); });
}

crowdgpu_result crowdgpu_model_event_time(crowdgpu_model model, uint32_t clip, uint32_t event, float* seconds) {
    if (!model || !seconds) return invalid("crowdgpu_model_event_time: model or seconds is NULL");
    return guarded([&] { *seconds = model->model.eventTime(clip, event); });
}

crowdgpu_result crowdgpu_model_event_joint(crowdgpu_model model, uint32_t clip, uint32_t event, int32_t* joint) {
    if (!model || !joint) return invalid("crowdgpu_model_event_joint: model or joint is NULL");
    return guarded([&] { *joint = model->model.eventJoint(clip, event); });
}
void crowdgpu_model_destroy(crowdgpu_model model) { delete model; }

crowdgpu_result crowdgpu_model_with_prop(crowdgpu_model model, const char* prop, const char* joint,
                                         const float offset[12], float share, crowdgpu_model* out) {
    if (!model || !prop || !joint || !out) return invalid("crowdgpu_model_with_prop: model, prop, joint or out is NULL");
    const std::string name = prop;
    if (name != "rifle" && name != "flag")
        return invalid(("crowdgpu_model_with_prop: no built-in prop '" + name + "' (rifle or flag)").c_str());
    return guarded([&] {
        crowdgpu::PropAttachment attachment{name == "rifle" ? crowdgpu::Prop::rifle() : crowdgpu::Prop::flag(), joint};
        if (offset) std::memcpy(attachment.offset, offset, sizeof attachment.offset);
        attachment.share = share;
        *out = new crowdgpu_model_t{model->model.withProps({attachment})};
    });
}

crowdgpu_result crowdgpu_model_with_gltf_prop(crowdgpu_model model, const char* path, const char* asset_root,
                                              const char* joint, const float offset[12], float share,
                                              crowdgpu_model* out) {
    if (!model || !path || !joint || !out)
        return invalid("crowdgpu_model_with_gltf_prop: model, path, joint or out is NULL");
    return guarded([&] {
        crowdgpu::PropAttachment attachment{crowdgpu::Prop::fromGltf(path, asset_root ? asset_root : ""), joint};
        if (offset) std::memcpy(attachment.offset, offset, sizeof attachment.offset);
        attachment.share = share;
        *out = new crowdgpu_model_t{model->model.withProps({attachment})};
    });
}

crowdgpu_result crowdgpu_crowd_create_grid(const crowdgpu_model* models, uint32_t model_count, uint32_t count,
                                           uint32_t seed, crowdgpu_behaviour behaviour, crowdgpu_crowd* out) {
    if (!out || !models || model_count == 0) return invalid("crowdgpu_crowd_create_grid: no models or out is NULL");
    return guarded([&] {
        std::vector<crowdgpu::Model> list;
        for (uint32_t i = 0; i < model_count; ++i) {
            if (!models[i]) throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument, "crowdgpu_crowd_create_grid: a NULL model");
            list.push_back(models[i]->model);
        }
        crowdgpu::GridLayout layout;
        layout.count = count;
        layout.seed = seed;
        *out = new crowdgpu_crowd_t{
            crowdgpu::Crowd::grid(std::move(list), layout, static_cast<crowdgpu::Behaviour>(stored(behaviour)))};
    });
}

crowdgpu_result crowdgpu_crowd_create(const crowdgpu_model* models, uint32_t model_count,
                                      const crowdgpu_character* characters, uint32_t count,
                                      const crowdgpu_capacity* capacity_in, uint32_t seed, crowdgpu_behaviour behaviour,
                                      crowdgpu_crowd* out) {
    if (!out || !models || model_count == 0 || (count > 0 && !characters))
        return invalid("crowdgpu_crowd_create: no models, characters NULL with a count, or out NULL");
    return guarded([&] {
        std::vector<crowdgpu::Model> list;
        for (uint32_t i = 0; i < model_count; ++i) {
            if (!models[i]) throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument, "crowdgpu_crowd_create: a NULL model");
            list.push_back(models[i]->model);
        }
        std::vector<crowdgpu::Character> people;
        people.reserve(count);
        for (uint32_t i = 0; i < count; ++i) people.push_back(characterOf(characters[i]));
        crowdgpu::CrowdCapacity capacity;
        if (capacity_in) {
            if (capacity_in->per_model) capacity.perModel.assign(capacity_in->per_model, capacity_in->per_model + model_count);
            capacity.drivenKeys = capacity_in->driven_keys;
        }
        *out = new crowdgpu_crowd_t{
            crowdgpu::Crowd(std::move(list), std::move(people), static_cast<crowdgpu::Behaviour>(behaviour), seed, capacity)};
    });
}

crowdgpu_result crowdgpu_crowd_spawn(crowdgpu_crowd crowd, const crowdgpu_character* c, crowdgpu_handle* handle) {
    if (!crowd || !c) return invalid("crowdgpu_crowd_spawn: crowd or character is NULL");
    return guarded([&] {
        const crowdgpu::CharacterHandle h = crowd->crowd.spawn(characterOf(*c));
        if (handle) *handle = {h.slot, h.generation};
    });
}

crowdgpu_result crowdgpu_crowd_remove(crowdgpu_crowd crowd, crowdgpu_handle handle) {
    if (!crowd) return invalid("crowdgpu_crowd_remove: crowd is NULL");
    return guarded([&] { crowd->crowd.remove({handle.slot, handle.generation}); });
}

crowdgpu_result crowdgpu_crowd_spawn_batch(crowdgpu_crowd crowd, const crowdgpu_character* characters, size_t count,
                                           crowdgpu_handle* handles) {
    if (!crowd) return invalid("crowdgpu_crowd_spawn_batch: crowd is NULL");
    if (count > 0 && (!characters || !handles))
        return invalid("crowdgpu_crowd_spawn_batch: characters or handles is NULL for a batch of " +
                       std::to_string(count));
    return guarded([&] {
        std::vector<crowdgpu::Character> batch(count);
        for (size_t i = 0; i < count; ++i) batch[i] = characterOf(characters[i]);
        std::vector<crowdgpu::CharacterHandle> made(count);
        crowd->crowd.spawn(batch.data(), count, made.data());
        for (size_t i = 0; i < count; ++i) handles[i] = {made[i].slot, made[i].generation};
    });
}

crowdgpu_result crowdgpu_crowd_remove_batch(crowdgpu_crowd crowd, const crowdgpu_handle* handles, size_t count) {
    if (!crowd) return invalid("crowdgpu_crowd_remove_batch: crowd is NULL");
    if (count > 0 && !handles)
        return invalid("crowdgpu_crowd_remove_batch: handles is NULL for a batch of " + std::to_string(count));
    return guarded([&] {
        std::vector<crowdgpu::CharacterHandle> batch(count);
        for (size_t i = 0; i < count; ++i) batch[i] = {handles[i].slot, handles[i].generation};
        crowd->crowd.remove(batch.data(), count);
    });
}

bool crowdgpu_crowd_alive(crowdgpu_crowd crowd, crowdgpu_handle handle) {
    return crowd && crowd->crowd.alive({handle.slot, handle.generation});
}

crowdgpu_result crowdgpu_crowd_handle(crowdgpu_crowd crowd, uint32_t slot, crowdgpu_handle* handle) {
    if (!crowd || !handle) return invalid("crowdgpu_crowd_handle: crowd or handle is NULL");
    return guarded([&] {
        const crowdgpu::CharacterHandle h = crowd->crowd.handle(slot);
        *handle = {h.slot, h.generation};
    });
}

uint32_t crowdgpu_crowd_live_count(crowdgpu_crowd crowd) { return crowd ? crowd->crowd.liveCount() : 0; }

crowdgpu_result crowdgpu_crowd_drive(crowdgpu_crowd crowd, const crowdgpu_handle* characters, const double* times,
                                     const float* x, const float* z, const float* headings, uint32_t count,
                                     uint32_t* applied, uint32_t* late) {
    if (!crowd) return invalid("crowdgpu_crowd_drive: crowd is NULL");
    return guarded([&] {
        static_assert(sizeof(crowdgpu_handle) == sizeof(crowdgpu::CharacterHandle));
        const crowdgpu::DriveResult r = crowd->crowd.drive(
            {reinterpret_cast<const crowdgpu::CharacterHandle*>(characters), times, x, z, headings, count});
        if (applied) *applied = static_cast<uint32_t>(r.applied);
        if (late) *late = static_cast<uint32_t>(r.late);
    });
}

crowdgpu_result crowdgpu_crowd_set_driven_timing(crowdgpu_crowd crowd, double delay, double extrapolate) {
    if (!crowd) return invalid("crowdgpu_crowd_set_driven_timing: crowd is NULL");
    return guarded([&] { crowd->crowd.setDrivenTiming({delay, extrapolate}); });
}

crowdgpu_result crowdgpu_crowd_gait_settings(crowdgpu_crowd crowd, uint32_t model, crowdgpu_gait_settings* out) {
    if (!crowd || !out) return invalid("crowdgpu_crowd_gait_settings: crowd or out is NULL");
    return guarded([&] {
        const crowdgpu::GaitSettings g = crowd->crowd.gaitSettings(model);
        *out = {g.walkFrom, g.runFrom, g.hysteresis, g.fade, g.turnRate, g.turnSpeed};
    });
}

crowdgpu_result crowdgpu_crowd_set_gait_settings(crowdgpu_crowd crowd, uint32_t model, const crowdgpu_gait_settings* s) {
    if (!crowd || !s) return invalid("crowdgpu_crowd_set_gait_settings: crowd or settings is NULL");
    return guarded([&] {
        crowd->crowd.setGaitSettings(model, {s->walk_from, s->run_from, s->hysteresis, s->fade, s->turn_rate, s->turn_speed});
    });
}

crowdgpu_result crowdgpu_crowd_set_terrain(crowdgpu_crowd crowd, uint32_t columns, uint32_t rows, const float* heights,
                                           const float origin[2], const float size[2]) {
    if (!crowd || ((columns || rows) && (!heights || !origin || !size)))
        return invalid("crowdgpu_crowd_set_terrain: crowd, heights, origin or size is NULL");
    return guarded([&] {
        crowdgpu::Heightfield field;
        field.columns = columns, field.rows = rows, field.heights = heights;
        if (origin) field.origin[0] = origin[0], field.origin[1] = origin[1];
        if (size) field.size[0] = size[0], field.size[1] = size[1];
        crowd->crowd.setTerrain(field);
    });
}

float crowdgpu_crowd_ground_height(crowdgpu_crowd crowd, float x, float z) {
    return crowd ? crowd->crowd.groundHeight(x, z) : 0.0f;
}

crowdgpu_result crowdgpu_crowd_set_world_bounds(crowdgpu_crowd crowd, const float lo[3], const float hi[3]) {
    if (!crowd) return invalid("crowdgpu_crowd_set_world_bounds: crowd is NULL");
    return guarded([&] { crowd->crowd.setWorldBounds(lo, hi); });
}

crowdgpu_result crowdgpu_crowd_move_to(crowdgpu_crowd crowd, uint32_t character, float x, float z, double at) {
    if (!crowd) return invalid("crowdgpu_crowd_move_to: crowd is NULL");
    return guarded([&] { crowd->crowd.moveTo(character, x, z, at); });
}

crowdgpu_result crowdgpu_crowd_play(crowdgpu_crowd crowd, uint32_t character, int32_t clip, double at, float fade) {
    if (!crowd) return invalid("crowdgpu_crowd_play: crowd is NULL");
    return guarded([&] { crowd->crowd.play(character, clip, at, fade); });
}

crowdgpu_result crowdgpu_crowd_advance_to(crowdgpu_crowd crowd, double time) {
    if (!crowd) return invalid("crowdgpu_crowd_advance_to: crowd is NULL");
    return guarded([&] { crowd->crowd.advanceTo(time); });
}

crowdgpu_result crowdgpu_set_worker_threads(uint32_t threads) {
    return guarded([&] { crowdgpu::setWorkerThreads(threads); });
}

uint32_t crowdgpu_worker_threads(void) { return crowdgpu::workerThreads(); }

crowdgpu_result crowdgpu_crowd_joint_world(crowdgpu_crowd crowd, uint32_t character, uint32_t joint, double time,
                                           float out[12]) {
    if (!crowd || !out) return invalid("crowdgpu_crowd_joint_world: crowd or out is NULL");
    return guarded([&] { crowd->crowd.jointWorld(character, joint, time, out); });
}

crowdgpu_result crowdgpu_crowd_events(crowdgpu_crowd crowd, const uint32_t* characters, uint32_t character_count,
                                      double from, double to, crowdgpu_event* out, uint32_t capacity, uint32_t* count) {
    if (!crowd || !count || (character_count > 0 && !characters) || (capacity > 0 && !out))
        return invalid("crowdgpu_crowd_events: crowd, characters, out or count is NULL");
    // Listed only when they fit the caller's buffer (`out` NULL, capacity 0: counted, nothing stored);
    // the list is reused per thread, so a host asking every frame allocates nothing once warm.
    thread_local std::vector<crowdgpu::Event> fired;
    return guarded([&] {
        const std::uint64_t total = crowd->crowd.events(characters, character_count, from, to, fired, capacity);
        const bool fits = total <= capacity;
        if (fits)
            for (std::size_t i = 0; i < fired.size(); ++i)
                out[i] = {fired[i].character, fired[i].clip, fired[i].event, fired[i].time};
        if (fired.capacity() > 65536) std::vector<crowdgpu::Event>().swap(fired);  // no high-water mark kept
        if (total > UINT32_MAX)
            throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument, "crowdgpu_crowd_events: more than 2^32 events");
        *count = static_cast<uint32_t>(total);
        if (!fits)
            throw crowdgpu::Error(crowdgpu::ErrorCode::InvalidArgument,
                                  "crowdgpu_crowd_events: " + std::to_string(total) + " events fired, room for " +
                                      std::to_string(capacity));
    });
}

uint32_t crowdgpu_crowd_size(crowdgpu_crowd crowd) { return crowd ? crowd->crowd.size() : 0; }

void crowdgpu_crowd_bounds(crowdgpu_crowd crowd, float center[3], float* radius, float* tallest) {
    if (!crowd || !center || !radius || !tallest) return;
    crowd->crowd.bounds(center, *radius, *tallest);
}

void crowdgpu_crowd_destroy(crowdgpu_crowd crowd) { delete crowd; }

void crowdgpu_enable_required_features(VkPhysicalDeviceFeatures2* f, VkPhysicalDeviceVulkan11Features* f11,
                                       VkPhysicalDeviceVulkan12Features* f12, VkPhysicalDeviceVulkan13Features* f13) {
    if (f && f11 && f12 && f13) crowdgpu::enableRequiredFeatures(*f, *f11, *f12, *f13);
}

void crowdgpu_renderer_settings_default(crowdgpu_renderer_settings* s) {
    if (!s) return;
    const crowdgpu::RendererSettings d;
    s->color_format = d.target.color;
    s->depth_format = d.target.depth;
    s->samples = d.target.samples;
    s->method = static_cast<crowdgpu_method>(d.method);
    s->gpu_animation = d.animation == crowdgpu::Animation::Gpu;
    s->lod = d.lod;
    s->impostors = d.impostors;
    s->shadows = d.shadows;
    s->impostor_threshold = d.impostorThreshold;
    s->mesh_capacity = d.meshCapacity;
    s->shadow_map_size = d.shadowMapSize;
    s->frames_in_flight = d.framesInFlight;
    s->raster = static_cast<crowdgpu_raster>(d.raster);
    s->mesh_raster_limit = d.meshRasterLimit;
    s->shadow_lod = d.shadowLod;
    s->shadow_raster_compute = d.shadowRaster == crowdgpu::ShadowRaster::Compute;
    s->impostor_blend = d.impostorBlend;
    s->lod_fade = d.lodFade;
    s->events = d.events;
    s->event_capacity = d.eventCapacity;
    s->shadow_cascades = d.shadowCascades;
    s->far_crowd = d.farCrowd;
    s->ground = d.ground;
    s->sky = d.sky;
    s->edge_filter = d.edgeFilter;
    s->terrain_samples = d.terrainSamples;
}

void crowdgpu_look_at(const float eye[3], const float target[3], float vertical_fov, float near_plane, float far_plane,
                      VkExtent2D extent, double time, crowdgpu_frame_view* out) {
    if (!eye || !target || !out) return;
    const crowdgpu::FrameView v = crowdgpu::lookAt(eye, target, vertical_fov, near_plane, far_plane, extent, time);
    std::memcpy(out->view, v.view, sizeof out->view);
    std::memcpy(out->projection, v.projection, sizeof out->projection);
    out->viewport = v.viewport;
    out->time = v.time;
}

uint64_t crowdgpu_memory_needed(VkPhysicalDevice physical_device, crowdgpu_crowd crowd,
                                const crowdgpu_renderer_settings* settings) {
    uint64_t bytes = 0;
    if (!crowd || !settings) return invalid("crowdgpu_memory_needed: crowd or settings is NULL"), 0;
    guarded([&] { bytes = crowdgpu::memoryNeeded(physical_device, crowd->crowd, settingsOf(*settings)); });
    return bytes;
}

crowdgpu_result crowdgpu_renderer_create(const crowdgpu_device* device, crowdgpu_crowd crowd,
                                         const crowdgpu_renderer_settings* settings, crowdgpu_renderer* out) {
    if (!device || !crowd || !settings || !out) return invalid("crowdgpu_renderer_create: an argument is NULL");
    return guarded([&] {
        const crowdgpu::Device d{device->instance, device->physical_device, device->device, device->queue_family,
                                 device->enabled_features};
        *out = new crowdgpu_renderer_t{crowdgpu::Renderer(d, crowd->crowd, settingsOf(*settings))};
    });
}

crowdgpu_result crowdgpu_renderer_record_setup(crowdgpu_renderer r, VkCommandBuffer cmd) {
    if (!r) return invalid("crowdgpu_renderer_record_setup: renderer is NULL");
    return guarded([&] { r->renderer.recordSetup(cmd); });
}

void crowdgpu_renderer_setup_completed(crowdgpu_renderer r) {
    if (r) r->renderer.setupCompleted();
}

crowdgpu_result crowdgpu_renderer_record_compute(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot,
                                                 const crowdgpu_frame_view* view, crowdgpu_crowd crowd) {
    if (!r || !view || !crowd) return invalid("crowdgpu_renderer_record_compute: renderer, view or crowd is NULL");
    return guarded([&] { r->renderer.recordCompute(cmd, slot, viewOf(*view), crowd->crowd); });
}

crowdgpu_result crowdgpu_renderer_record_compute_samples(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot,
                                                         const crowdgpu_frame_view* view, crowdgpu_crowd crowd,
                                                         const crowdgpu_device_samples* samples) {
    if (!r || !view || !crowd || !samples)
        return invalid("crowdgpu_renderer_record_compute_samples: renderer, view, crowd or samples is NULL");
    return guarded([&] {
        r->renderer.recordCompute(cmd, slot, viewOf(*view), crowd->crowd, {samples->buffer, samples->offset, samples->size});
    });
}

crowdgpu_result crowdgpu_renderer_record_shadows(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot) {
    if (!r) return invalid("crowdgpu_renderer_record_shadows: renderer is NULL");
    return guarded([&] { r->renderer.recordShadows(cmd, slot); });
}

crowdgpu_result crowdgpu_renderer_record_ground(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot) {
    if (!r) return invalid("crowdgpu_renderer_record_ground: renderer is NULL");
    return guarded([&] { r->renderer.recordGround(cmd, slot); });
}

crowdgpu_result crowdgpu_renderer_record_characters(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot) {
    if (!r) return invalid("crowdgpu_renderer_record_characters: renderer is NULL");
    return guarded([&] { r->renderer.recordCharacters(cmd, slot); });
}

crowdgpu_result crowdgpu_renderer_record_edge_filter(crowdgpu_renderer r, VkCommandBuffer cmd, uint32_t slot,
                                                     VkImageView source, VkImageView destination, VkExtent2D extent) {
    if (!r) return invalid("crowdgpu_renderer_record_edge_filter: renderer is NULL");
    return guarded([&] { r->renderer.recordEdgeFilter(cmd, slot, source, destination, extent); });
}

void crowdgpu_renderer_destroy(crowdgpu_renderer r) { delete r; }

}  // extern "C"
