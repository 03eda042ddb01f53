// crowdgpu: the GPU renderer on a device the host lends it (link crowdgpu::renderer).
//
// The host creates the Vulkan instance and device (Vulkan 1.3, with the features deviceRequirements
// lists), owns every command buffer, queue submission, fence and semaphore, and the images it draws
// into. The renderer records into the host's command buffers:
//
//   recordSetup(cmd)              once (and after setImpostors(true)): uploads, the impostor bake.
//                                 Submit it before the first frame; call setupCompleted() once that
//                                 submission has finished (frees its staging memory).
//   per frame, in frame slot s (0 .. framesInFlight-1, the host's; wait for the slot's previous
//   frame before recording it again):
//   recordCompute(cmd, s, view, crowd)
//                                 outside any rendering pass: the crowd's changes since the last frame
//                                 (spawns, removals, replans), motion, culling and LOD, bone palettes,
//                                 skinning, impostor lists.
//   recordShadows(cmd, s)         outside any rendering pass: the casters into the renderer's own
//                                 shadow map (when shadows are on).
//   recordGround(cmd, s)          optional, inside the host's colour pass: a checkered ground, drawn
//                                 at once (RendererSettings::ground draws it more cheaply instead).
//   recordCharacters(cmd, s)      inside the host's colour pass (dynamic rendering, begun by the host
//                                 with the colour and depth formats and sample count of `target`);
//                                 with RendererSettings::ground and ::sky it draws the ground and sky
//                                 too, and the host need not clear its colour attachment.
//   recordEdgeFilter(cmd, s, ...) optional, after the host's colour pass: anti-aliasing in compute
//                                 (RendererSettings::edgeFilter).
//
// Nothing in the frame path submits, waits or signals. A frame the host records and then drops (never
// submits) is safe: the next frame that finds it never ran uploads again what it carried. Depth is 0 at the near plane and 1 at the far
// one, tested with LESS; the projection is Vulkan's (y down). Colour is written as linear RGB: an
// sRGB or float target shows it right. Not thread-safe: one thread records a renderer.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"

namespace crowdgpu {

namespace detail { struct RendererData; }

// ---- What the device must have ----

struct DeviceRequirements {
    std::uint32_t apiVersion;  // VK_API_VERSION_1_3
    std::vector<const char*> extensions;  // device extensions (none today)
    std::vector<const char*> features;    // names, as in the Vulkan feature structs
};
DeviceRequirements deviceRequirements();
// Sets the features the library needs to VK_TRUE in the host's chain for vkCreateDevice (leaves the
// others as they are). The structs are the host's; chain them as usual.
void enableRequiredFeatures(VkPhysicalDeviceFeatures2& features, VkPhysicalDeviceVulkan11Features& vulkan11,
                            VkPhysicalDeviceVulkan12Features& vulkan12, VkPhysicalDeviceVulkan13Features& vulkan13);
// Empty when the physical device supports everything needed; else a line naming what it lacks.
std::string checkPhysicalDevice(VkPhysicalDevice physicalDevice);

// What the host lends. The library destroys none of it; the host destroys it after the renderers.
struct Device {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queueFamily = 0;  // of the queue the host submits the renderer's commands to
    // The VkPhysicalDeviceFeatures2 chain the device was created with (1.1, 1.2 and 1.3 structs
    // chained): checked for every feature the library needs.
    const VkPhysicalDeviceFeatures2* enabledFeatures = nullptr;
};

class Renderer;

// The colour the ground and far characters fade into with distance (linear RGB): a host that clears
// its target to it gets a seamless horizon.
inline constexpr float kHorizonColor[3] = {0.55f, 0.7f, 0.9f};

// ---- Settings ----

enum class Method { TwoPass, TwoPassDirect, VertexShader, VertexShaderInstanced, Compute, Static };
enum class Animation { Gpu, Cpu };
enum class Culling { Gpu, Cpu, Off };
// How the shadow map's casters are rasterized: by the graphics pipeline, or in compute (a 32-bit
// atomic min of depth per texel, on every shader core instead of the graphics slice). Compute applies
// to the methods whose skinned vertices are in a buffer (all but vs and vs-instanced, which keep the
// graphics pipeline for every caster); the impostor-level casters go with the meshes.
enum class ShadowRaster { Hardware, Compute };
// Which rasterizer draws the impostors (docs/compute-raster.md): the hardware's; a compute pass into a
// visibility buffer (64-bit atomics), resolved in the colour pass; or each impostor by its size on
// screen (small ones in compute). Compute needs shaderInt64 and shaderBufferInt64Atomics enabled on the
// device (else Renderer throws Unsupported); auto falls back to hardware. With a multisampled target,
// what compute draws fills all samples of its pixels: merged by depth, its own edges not anti-aliased.
enum class Raster { Hardware, Compute, Auto };
// Names for reports and menus: "two-pass", "two-pass-direct", "vs", "vs-instanced", "compute",
// "static"; "gpu", "cpu"; "gpu", "cpu", "off"; "hardware", "compute".
const char* methodName(Method method);
const char* animationName(Animation animation);
const char* cullingName(Culling culling);
const char* shadowRasterName(ShadowRaster raster);
const char* rasterName(Raster raster);  // "hardware", "compute", "auto"

// The host's colour pass.
struct TargetFormat {
    VkFormat color = VK_FORMAT_R8G8B8A8_SRGB;
    VkFormat depth = VK_FORMAT_D32_SFLOAT;
    // Samples per pixel of the colour pass (multisampling): the ground, character and impostor
    // pipelines are made for it; above one, impostors turn their coverage into the samples they cover.
    // Resolving into a single-sample image is the host's (at the end of its pass). The shadow map is
    // the renderer's own and single-sampled.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

struct RendererSettings {
    TargetFormat target;
    Method method = Method::TwoPass;  // the paper's: fragment-shader skinning, copied to a vertex buffer
    Animation animation = Animation::Gpu;
    Culling culling = Culling::Gpu;
    bool lod = true;
    float lodThresholds[2] = {150.0f, 50.0f};  // pixels of pose-sphere diameter for LOD 0 and 1
    float lodHysteresis = 0.1f;
    // Level changes fade: across a band of sizes the coarser level's share rises, so no change pops
    // (hysteresis is then not needed). Between mesh levels the finer level's shape morphs into the
    // coarser one as it is skinned (drawn once), over the band from T (1 + 2 lodHysteresis) down to the
    // threshold T, where the coarser level takes over; into its impostor a character is drawn at both,
    // each on a complementary screen-space dither of its pixels, over T (1 +- lodHysteresis). With the
    // methods that skin into a buffer every frame; VertexShader, VertexShaderInstanced and Static do
    // not fade. Fades cost nothing measurable on the H200 (docs/picture-quality.md). Off: levels
    // switch at once, with hysteresis.
    bool lodFade = true;
    bool impostors = false;          // characters under impostorThreshold pixels as animated impostors
    float impostorThreshold = 32.0f;
    // Impostors blend the two nearest views, elevation bands and animation frames (eight atlas cells,
    // four where the view lies below the lowest band's middle or above the highest's); off: the nearest
    // cell alone, cheaper (one texture fetch where up to eight were) but stepping visibly.
    bool impostorBlend = true;
    // The far crowd averaged: impostors a few pixels across (16 px or less) drawn by the compute
    // rasterizer add their coverage to a layer blended over the picture, so a crowd seen from far is a
    // stable average, not single pixels that flicker as the camera moves, and closer to the meshes they
    // stand for (docs/picture-quality.md). On by default, set by measurement: on the H100 it is closer
    // to a supersampled render of the meshes (+8 dB) and 27 % faster at 1,000,000 from above.
    // Off: they win whole pixels or none (cut at half coverage). No effect on the hardware path.
    bool farCrowd = true;
    // recordCharacters draws the checkered ground too: after the opaque characters and before the far
    // crowd's blended layer, so the depth test rejects the ground under them before it is shaded. The
    // picture is recordGround's before recordCharacters, pixel for pixel; on an H100 the frame is 7 %
    // shorter at paper-fig4 (docs/gpu-driven-frame.md, "The ground behind the characters"). With it on,
    // recordGround is refused; off: no ground unless the host records one.
    bool ground = false;
    // recordCharacters ends by colouring every pixel still at the cleared depth with kHorizonColor (a
    // triangle at the far plane, tested less-or-equal, depth not written), before the far crowd's layer:
    // every pixel of the viewport is then written, so the host can begin its pass with the colour
    // attachment's loadOp DONT_CARE instead of a clear. On an H200's graphics slice (the H100's) a
    // 1080p colour clear costs 0.15 ms a sample per pixel; the sky costs that only where it shows
    // (docs/gpu-driven-frame.md, "The sky instead of a colour clear"). Off: the host clears (to kHorizonColor
    // for a seamless horizon) or draws its own background, which with the sky on would be painted over
    // unless it writes depth.
    bool sky = false;
    // An edge filter for the finished picture: anti-aliasing in compute after the host's colour pass
    // (Renderer::recordEdgeFilter), FXAA-like. Each pixel is read and written once on every shader core,
    // where multisampling fills each sample on the graphics slice: on an H200 0.037 ms at 1920x1080,
    // +1.9 % of paper-fig4's frame where 2 samples cost +47 %, for about what 2 samples gain
    // (docs/picture-quality.md, "The edge filter"). It smooths every edge of the picture, what the
    // compute rasterizer draws included, but finds edges by contrast only: it gains less than 4 samples
    // do and softens high-contrast texture a little. Off: nothing is made for it and recordEdgeFilter
    // is refused.
    bool edgeFilter = false;
    std::uint32_t meshCapacity = 65536;  // with impostors: the most characters drawn as meshes a frame
                                         // (beyond it, the smallest on screen become impostors)
    Raster raster = Raster::Auto;  // the impostors' rasterizer (hardware: the frame as before it; auto falls back
                                   // to hardware without 64-bit atomics)
    // Under Raster::Auto, the largest character (its pose sphere's diameter on screen, pixels) whose mesh
    // the compute rasterizer draws, for methods that skin into a buffer; larger ones stay on the hardware.
    // -1 (automatic): 64 px, on frames whose frame slot's previous frame drew at least 4,000,000 mesh
    // triangles (where the hardware rasterizer is the wall); 0: never; a limit: every frame.
    // Raster::Compute draws every mesh it can (wholly in front of the eye) in compute
    // (docs/compute-raster.md, "Meshes").
    float meshRasterLimit = -1.0f;
    bool shadows = true;
    // Casters drawn into the shadow map at a level from their size in the map (texels of pose-sphere
    // diameter, the LOD thresholds' values), never finer than in view, and those under 2 texels not at
    // all; off: at their level in view.
    bool shadowLod = true;
    ShadowRaster shadowRaster = ShadowRaster::Compute;
    std::uint32_t shadowMapSize = 2048;
    // Cascades of the shadow map, 1 to 4, split by distance from the camera: with 2 to 4 each takes a
    // quarter of the map over its stretch of the view, so near shadows get finer texels and far ones
    // coarser, for a cost (docs/gpu-driven-frame.md, "Shadow cascades": paper-fig4's frame +24 % over no
    // shadows with one, +53 % with two, +84 % with four on an H100). 1: one map over the whole view.
    // 2 to 4 need a map of at least 64 texels.
    std::uint32_t shadowCascades = 1;
    std::uint32_t framesInFlight = 2;
    // Animation events (clip events: footsteps, a glTF clip's own) of the characters in view, written
    // each frame to FrameOutput::events for the host's own passes (docs/events.md). Costs one pass
    // after culling (a thread per character, work only where one fires) and a buffer of eventCapacity
    // 32-byte records (2 MiB); off: neither.
    bool events = true;
    std::uint32_t eventCapacity = 65536;  // records a frame keeps (1 to 4,000,000); the rest are counted
    // Room for a terrain of this many heights set after the renderer is made (Crowd::setTerrain; 4 bytes each
    // on the device); the crowd's own terrain when the renderer is made always fits. 0: that one.
    std::uint32_t terrainSamples = 0;
    // A renderer of the same models in the same order whose baked impostor atlas this one shares
    // instead of baking its own (it must have completed setup); null: bake when impostors turn on.
    const Renderer* impostorsFrom = nullptr;
};

// One frame's view: column-major 4x4 matrices as glm and Vulkan use them (m[column * 4 + row]).
struct FrameView {
    float view[16];
    float projection[16];  // perspective, Vulkan clip space (y down, depth 0..1)
    VkRect2D viewport;     // pixels of the host's target
    double time;           // seconds on the crowd's clock (a double: exact at any scene time)
};

// A view and projection looking from `eye` at `target` (y up), for hosts without their own.
FrameView lookAt(const float eye[3], const float target[3], float verticalFov, float nearPlane, float farPlane,
                 VkExtent2D extent, double time);

struct MemoryItem {
    std::string what;
    std::uint64_t bytes;
};

// The characters and triangles drawn per level in a slot's last frame (read after its fence).
struct FrameCounts {
    std::uint32_t characters[3];
    std::uint64_t triangles[3];
    std::uint32_t impostors;
    std::uint32_t demoted;  // impostors only because the mesh capacity was full
    std::uint64_t skinnedVertices;  // what the skinning pass skinned: visible characters x their LOD's vertices
    // The shadow pass: mesh casters and their triangles per shadow level, impostors casting a quad.
    std::uint32_t shadowCharacters[3];
    std::uint64_t shadowTriangles[3];
    std::uint32_t shadowImpostors;
    // The frame's device samples (DeviceSamples): made into keys, late (no later than their character's
    // newest key: ignored), and refused (a non-finite position or an infinite heading).
    struct {
        std::uint32_t applied, late, refused;
    } deviceSamples;
};

// One sample of a character driven by a device buffer (MotionSource::DeviceSamples), as the host's
// own pass writes it (std430, 16 bytes): where the character was `time` seconds relative to the
// frame's time (FrameView::time; 0: at the frame's time; a past sample is negative), on the ground at
// (x, z) world metres, facing `heading` radians about +y (NaN: towards the motion). A sample whose time
// is not a number says "nothing new": write NaN for a character without a sample this frame. It
// becomes a key when it is later than the character's newest, as Crowd::drive's samples do.
struct DeviceSample {
    float time;
    float x, z;
    float heading;
};
// The host's buffer of device samples for a frame: DeviceSample s of slot s at offset + 16 s, for every
// slot of the crowd (Crowd::size()): `size` bytes from `offset` (at least 16 x slots), the offset a
// multiple of minStorageBufferOffsetAlignment. Made with VK_BUFFER_USAGE_STORAGE_BUFFER_BIT; the host's
// writes made visible to VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT storage reads before recordCompute (its
// barrier), and its next writes wait for this frame's compute-shader reads.
struct DeviceSamples {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
};

// This frame's skinned characters, for the host's own passes (G-buffer, outline, picking): bind
// `positions` at `positionsOffset` and `normals` at `normalsOffset` as vec4 vertex streams, `indices`
// as uint32 indices, and draw with vkCmdDrawIndexedIndirectCount(draws, 0, drawCount,
// drawCountOffset, maxDraws, 20). firstInstance of each draw is the character's index. Valid after
// recordCompute of the frame, for the methods that skin into a buffer (not VertexShader*:
// `skinned` is false there). With lodFade on, a character fading into its impostor has no instance in
// `draws` (the renderer draws it dithered from a list of its own): draw also
// vkCmdDrawIndexedIndirectCount(draws, fadingDrawsOffset, drawCount, fadingCountOffset, maxDraws, 20).
// One fading between mesh levels is in `draws`, its vertices already morphed.
struct FrameOutput {
    bool skinned = false;
    VkBuffer vertices = VK_NULL_HANDLE;
    VkDeviceSize positionsOffset = 0, normalsOffset = 0;
    VkBuffer indices = VK_NULL_HANDLE;
    VkBuffer draws = VK_NULL_HANDLE;
    VkBuffer drawCount = VK_NULL_HANDLE;
    VkDeviceSize drawCountOffset = 0;
    std::uint32_t maxDraws = 0;
    VkDeviceSize fadingDrawsOffset = 0, fadingCountOffset = 0;  // lodFade: draws of those fading into impostors
    // With events on: the clip events that characters in view fired in (the previous recordCompute's
    // time, this one's] (nothing on the first frame or when time goes back): a GpuEventHeader at byte
    // 0, then header.count GpuEvents from eventsOffset, in no particular order. Null with events off.
    VkBuffer events = VK_NULL_HANDLE;
    VkDeviceSize eventsOffset = 16;
    std::uint32_t eventCapacity = 0;
    // Stages and accesses the renderer wrote these with: a host pass reading them needs no barrier of
    // its own when it runs after recordCompute in the same queue (the renderer's own barrier covers
    // vertex input and indirect reads); these are for hosts that read them in compute.
    VkPipelineStageFlags2 writtenBy = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
};

// The event buffer's layout (FrameOutput::events; std430, as the shaders write it).
struct GpuEventHeader {
    std::uint32_t count;         // events written (at most capacity)
    std::uint32_t dropped;       // events that fired in view but found the buffer full (not written)
    std::uint32_t capacity;
    std::uint32_t lostSegments;  // characters replanned in the window beyond the previous-segment table (its
                                 // size: min(crowd, capacity, 65,536)): their events before the replan are missing
};
struct GpuEvent {
    std::uint32_t character;
    std::uint32_t clip;   // the model's clip (Model::eventName(clip, event) names it)
    std::uint32_t event;  // index among that clip's events
    std::uint32_t unused;
    float position[3];    // world: the event's joint where the character is then (its root without a joint)
    float age;            // seconds before the frame's time it fired (>= 0)
};

// Called as each pass ends, outside any rendering pass (timestamps, debug labels).
using PassObserver = std::function<void(VkCommandBuffer cmd, const char* pass)>;

// Device bytes a renderer with these settings takes for this crowd: the sum of what the renderer's
// constructor allocates, from the same planner. Compare with the device's heap before creating one.
// This and the two queries below throw Error(InvalidArgument) for a null physical device.
std::uint64_t memoryNeeded(VkPhysicalDevice physicalDevice, const Crowd& crowd, const RendererSettings& settings);

// Whether the device's limits allow this crowd with these settings: the most characters of the
// crowd's mix (same models, same shares) whose storage-buffer bindings fit maxStorageBufferRange,
// and, when this crowd is over it, the first binding past it in one line (the constructor refuses
// with the same words). `meshCapacityBound`: that binding is sized by settings.meshCapacity.
struct DeviceLimitCheck {
    std::uint64_t mostCharacters = 0;
    std::string problem;  // empty: fits
    bool meshCapacityBound = false;
};
DeviceLimitCheck checkDeviceLimits(VkPhysicalDevice physicalDevice, const Crowd& crowd, const RendererSettings& settings);

// Why recordCompute would refuse a viewport of `extent` with these settings on this device, in one line
// (empty: it draws it): past maxViewportDimensions, or, with Raster::Compute, a visibility buffer (8
// bytes a pixel) past maxStorageBufferRange. Raster::Auto draws such a viewport with the hardware
// rasterizer instead (and leaves the far crowd's layer, 32 bytes a pixel, out where it does not fit).
std::string viewportProblem(VkPhysicalDevice physicalDevice, const RendererSettings& settings, VkExtent2D extent);

class Renderer {
public:
    // Builds pipelines for settings.target and allocates buffers for the crowd's slots (its capacity:
    // Crowd::size()); their contents wait in recordSetup. Throws Error: Unsupported (a feature missing
    // from Device::enabledFeatures, a format the device cannot render to), OutOfDeviceMemory (over
    // memoryNeeded's budget), or InvalidArgument (a value that is no Vulkan 1.3 format or no value of its
    // enum, checked before any Vulkan call sees it; docs/embedding.md, "Argument ranges"). The renderer
    // keeps no reference to the crowd (it keeps its models alive): each recordCompute is handed the crowd.
    Renderer(const Device& device, const Crowd& crowd, const RendererSettings& settings);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    bool setupPending() const;
    void recordSetup(VkCommandBuffer cmd);
    void setupCompleted();

    // `crowd`: the crowd the renderer was made for, or another of the same layout (the same models in the
    // same order, each slot's model the same; else Error(InvalidArgument)), advanced to view.time. Uploads
    // the slots it changed since the last frame (everything for another crowd than the last frame's):
    // 100 bytes a changed slot. A frame recorded here and never submitted is safe (see above).
    void recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const FrameView& view, const Crowd& crowd);
    // The same with the host's device samples of this frame: they become the keys of the characters driven
    // by a device buffer, on the GPU, before the motion pass (no CPU copy: a thread a slot). GPU animation only. Refused, before anything is recorded, for a buffer smaller than the slots'
    // samples, an unaligned offset, or a crowd made without driven keys.
    void recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const FrameView& view, const Crowd& crowd,
                       const DeviceSamples& samples);
    void recordShadows(VkCommandBuffer cmd, std::uint32_t slot);
    void recordGround(VkCommandBuffer cmd, std::uint32_t slot) const;
    void recordCharacters(VkCommandBuffer cmd, std::uint32_t slot);
    // With RendererSettings::edgeFilter, after the host's colour pass (outside any rendering pass): the
    // picture in `source` anti-aliased into `destination`, both images of `extent` pixels, the host's.
    //   source: a sampled view of the finished colour (any format the device filters linearly), in
    //     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, the pass's writes made visible to compute-shader
    //     sampled reads (the host's barrier).
    //   destination: another image's VK_FORMAT_R8G8B8A8_UNORM view with storage usage, in
    //     VK_IMAGE_LAYOUT_GENERAL. When target.color is an sRGB format it is taken to be a UNORM view of
    //     an sRGB image (made with VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT) and the filter writes
    //     sRGB-encoded values; else linear ones. Written by compute-shader storage writes: the host's
    //     barrier makes them visible to what reads the picture next.
    // Once per slot a frame: each call rewrites the slot's descriptor set.
    void recordEdgeFilter(VkCommandBuffer cmd, std::uint32_t slot, VkImageView source, VkImageView destination,
                          VkExtent2D extent);
    FrameOutput output() const;
    FrameCounts counts(std::uint32_t slot) const;
    // Frames recorded and then never submitted, found as their slots came round (their uploads went again).
    std::uint64_t framesLost() const;
    void setPassObserver(PassObserver observer);

    // Between frames, with the GPU idle (the host waits for its frames first): these rebuild
    // resources. setImpostors(true) the first time bakes the atlas: setup work (recordSetup again).
    void setMethod(Method method);
    void setShadows(bool on);
    void setShadowLod(bool on);
    void setShadowRaster(ShadowRaster raster);
    void setShadowCascades(std::uint32_t count);  // as RendererSettings::shadowCascades
    void setLodFade(bool on);
    void setImpostorBlend(bool on);
    void setFarCrowd(bool on);
    void setGround(bool on);  // as RendererSettings::ground; between frames
    void setCulling(Culling culling, bool lod);
    void setImpostors(bool on);
    void setAnimation(Animation animation);
    // Pixel thresholds of the levels of detail and the impostors (as in RendererSettings).
    void setLevels(const float lodThresholds[2], float lodHysteresis, float impostorThreshold);
    const RendererSettings& settings() const;

    // Device memory by resource, as allocated.
    std::vector<MemoryItem> memory() const;
    // The same bytes divided by the crowd's size, by what they are for: "state" (records, motion, LOD
    // state, lists), "bones", "mesh slots" (skinned vertices and draw lists), "atlas", "fixed" (the
    // geometry, clips and shadow map).
    std::map<std::string, double> memoryPerCharacter() const;
    // Whether recordCompute animates on the CPU (settings.animation == Cpu, or a method that needs
    // CPU palettes): the host's recordCompute call then costs the CPU animation of the crowd.
    bool animatesOnCpu() const;
    // Host milliseconds the impostor atlas's construction took (planning and recording its bake); 0
    // without one.
    double impostorBakeMs() const;

    // The library's side (opaque to hosts).
    explicit Renderer(std::unique_ptr<detail::RendererData> data);
    detail::RendererData& data() { return *data_; }
    const detail::RendererData& data() const { return *data_; }

private:
    std::unique_ptr<detail::RendererData> data_;
};

}  // namespace crowdgpu
