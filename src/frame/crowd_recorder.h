#pragma once
// The crowd's frame as record calls into command buffers somebody else owns and submits:
//   recordSetup       uploads and the impostor bake (once, and again after setCull turns impostors on)
//   recordCompute     outside any rendering pass: CPU animation upload or GPU motion -> cull and LOD
//                     -> GPU palettes -> skinning (the method) -> compute raster of impostors (--raster
//                     compute|auto) -> impostor lists -> shadow map clear
//   recordShadows     the shadow casters into the renderer's own shadow map (a depth pass of its own)
//   recordGround      inside the host's colour pass: the checkered ground (optional; refused with `ground` on)
//   recordCharacters  inside the host's colour pass: the characters, then the impostors (hardware-drawn,
//                     then the visibility buffer's resolve), then with `ground` on the ground behind them,
//                     with `sky` on the sky where nothing is, then the far crowd's blended layer
// Nothing here submits, waits or signals. A frame slot's resources (bone staging, readback of the
// level counts, uniforms) are reused when the slot comes round again: the host must have waited for
// that slot's previous frame first. The crowd is planned by its owner (crowd::Crowd::advanceTo).
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "crowd/crowd.h"
#include "gpu/pass_observer.h"
#include "render/animation_pass.h"
#include "render/camera.h"
#include "render/camera.h"
#include "render/character_draw.h"
#include "render/crowd_buffers.h"
#include "render/cull_pass.h"
#include "render/draw_lists.h"
#include "render/event_pass.h"
#include "render/frame_ledger.h"
#include "render/frame_view.h"
#include "render/geometry_pool.h"
#include "render/ground_sunlight.h"
#include "render/impostor_atlas.h"
#include "render/impostor_draw.h"
#include "render/impostor_raster.h"
#include "render/impostor_shadow_raster.h"
#include "render/mesh_raster.h"
#include "render/raster_mode.h"
#include "render/scene_pass.h"
#include "render/shadow_cascades.h"
#include "render/shadow_map.h"
#include "render/shadow_raster.h"
#include "render/terrain_buffer.h"
#include "render/target_format.h"
#include "skin/skinning_method.h"

namespace gpu { class VulkanContext; }

namespace frame {

struct RecorderOptions {
    render::TargetFormat target;  // the colour pass recordCharacters draws into
    skin::Method method = skin::Method::TwoPass;
    render::AnimationPath animation = render::AnimationPath::Gpu;
    render::CullSettings cull;
    bool shadows = true;                 // the directional light's shadow map, drawn from the same skinned vertices
    // Impostors blend the nearest cells (views, elevation bands and frames; docs/impostors.md), or show the nearest.
    bool impostorBlend = true;
    // Compute-rasterized impostors up to farCrowdPixels across add their coverage to the far layer
    // instead of winning whole pixels (docs/picture-quality.md, "The far crowd averaged"); off: the
    // half-coverage cut for every impostor.
    bool farCrowd = true;
    float farCrowdPixels = render::kFarCrowdPixels;
    // Tests: 0 averages the smallest far impostors by sub-samples too, the reference of their splats.
    float farCrowdSplatPixels = render::kFarCrowdSplatPixels;
    std::uint32_t shadowMapSize = 2048;  // texels per side
    // recordCharacters draws the checkered ground after the opaque characters (crowdgpu::RendererSettings::ground).
    bool ground = false;
    // recordCharacters ends with the sky (crowdgpu::RendererSettings::sky): every pixel nothing else drew
    // gets the sky colour, so the host need not clear its colour target.
    bool sky = false;
    // The shadow map's mesh casters through the graphics rasterizer or a compute pass (render/shadow_raster.h).
    render::ShadowRasterPath shadowRaster = render::ShadowRasterPath::Compute;
    // Cascades of the shadow map, split by distance (render/shadow_cascades.h): 1 to 4.
    std::uint32_t shadowCascades = render::kDefaultShadowCascades;
    std::uint32_t framesInFlight = 2;
    std::uint32_t maxTargetDimension = 0;  // 0: device limit
    // Tests: the ground's tiles point-sampled, as before they were filtered (issue 19), to measure
    // what filtering them gains.
    bool pointSampledGround = false;
    // Tests: the ground's sunlight from nine shadow-map comparisons per pixel, as before the ground
    // sunlight image (render/ground_sunlight.h), the reference its pictures are compared with.
    bool perPixelGroundShadows = false;
    // With impostors on at construction (cull.impostors), the most characters drawn at a mesh level
    // (LOD 0-2) in a frame: skinned vertices, visible lists and draws are sized for it, and culling
    // demotes the characters beyond it to impostors. 0, or a crowd no larger: no cap.
    std::uint32_t meshCapacity = 0;
    render::ImpostorSettings impostorSettings;
    // Which rasterizer draws the impostors (docs/compute-raster.md). Compute is refused without 64-bit
    // buffer atomics; auto then falls back to the hardware.
    render::RasterMode raster = render::RasterMode::Hardware;
    // Under auto, the largest impostor (screen rectangle's longer side, pixels) drawn in compute.
    float rasterLimitPixels = render::kAutoRasterLimitPixels;
    // Under auto, the largest character (pose sphere's diameter on screen, pixels) whose mesh is drawn in
    // compute (render/mesh_raster.h), every frame; 0: none; render::kMeshRasterAutomatic: the automatic
    // limit on frames whose slot's previous frame drew at least meshRasterMinTriangles mesh triangles.
    float meshRasterLimitPixels = render::kMeshRasterAutomatic;
    std::uint64_t meshRasterMinTriangles = render::kAutoMeshRasterMinTriangles;
    // The compute rasterizers' resolve: over the screen tiles of this side they drew into
    // (render/visibility_resolve.h). Tests and measurements: 0 resolves every pixel of the viewport, the
    // reference the tiles must match.
    std::uint32_t resolveTilePixels = render::kResolveTilePixels;
    // Animation events of the characters in view, into a buffer for the host (render/event_pass.h);
    // the buffer keeps eventCapacity records a frame.
    bool events = true;
    std::uint32_t eventCapacity = render::kDefaultEventCapacity;
    // Room for a terrain of this many heights set after the renderer is made (the crowd's own, when more).
    std::uint32_t terrainSamples = 0;
    // An atlas baked before for the same models in the same order (tests, benchmarks): not baked again.
    std::shared_ptr<const render::ImpostorAtlas> atlas;
    // Kept alive by what may outlive the recorder (its atlas, shared with other recorders): the
    // owner of the context, when the context is not the caller's for longer.
    std::shared_ptr<const void> contextOwner;
};

// The mesh-level cap in effect: options.meshCapacity when impostors are on from the start to take the
// characters beyond it and it is below the crowd's size, else 0 (no cap).
std::uint32_t meshCapacityInEffect(const RecorderOptions& options, const crowd::Crowd& crowd);
// Why a viewport of `extent` cannot be drawn with this raster mode on a device with these limits, in one
// line (empty: it can): past maxViewportDimensions, or, under raster compute, a visibility buffer past
// maxStorageBufferRange (raster auto draws such a viewport on the hardware). recordCompute refuses it.
std::string viewportProblem(const VkPhysicalDeviceLimits& limits, const std::string& deviceName, render::RasterMode raster,
                            VkExtent2D extent);
// The most characters a frame lists at a mesh level (DrawLists::drawCapacity): the mesh slots, and
// the bone blocks when they belong to slots.
std::uint32_t meshSlots(const RecorderOptions& options, const crowd::Crowd& crowd);

// The rasterizer the impostors get: options.raster where the device allows it (64-bit buffer atomics),
// hardware for auto where it does not; compute where it does not throws gpu::Error (Unsupported)
// saying why in one line. Multisampled targets keep the compute rasterizers (render/raster_mode.h).
render::RasterMode rasterInEffect(const gpu::VulkanContext& context, const RecorderOptions& options);

// Where this frame's skinned characters are, for a host's own passes (G-buffer, outline, picking):
// draw with the method's vertices and the geometry pool's indices from the indirect commands.
struct FrameOutput {
    render::DrawInput input = render::DrawInput::SkinnedVertices;
    render::SkinnedVertices vertices;  // skinned positions and normals (DrawInput::SkinnedVertices)
    VkBuffer indices = VK_NULL_HANDLE;  // uint32, every model and LOD
    VkBuffer draws = VK_NULL_HANDLE;    // VkDrawIndexedIndirectCommand per visible (character, LOD)
    VkBuffer drawCount = VK_NULL_HANDLE;  // uint32 count of `draws`, at drawCountOffset
    VkDeviceSize drawCountOffset = 0;
    std::uint32_t maxDraws = 0;
    // With fades on, a character fading into its impostor has no instance in the draws above; its
    // mesh's draw is in `draws` from fadingDrawsOffset (bytes), counted at fadingCountOffset of
    // `drawCount`. Characters fading between mesh levels are in the draws above, morphed.
    VkDeviceSize fadingDrawsOffset = 0;
    VkDeviceSize fadingCountOffset = 0;
    VkBuffer characters = VK_NULL_HANDLE;  // CharacterRecord per character (firstInstance names it)
    // With events on: gpu::EventHeader, then up to eventCapacity gpu::EventRecords from byte 16.
    VkBuffer events = VK_NULL_HANDLE;
    std::uint32_t eventCapacity = 0;
};

class CrowdRecorder {
public:
    // Laid out for `crowd` (its slots and models, which must outlive the recorder; the crowd itself
    // need not: each frame is handed the crowd to draw). Pipelines are built for options.target.
    CrowdRecorder(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RecorderOptions& options);
    ~CrowdRecorder();
    CrowdRecorder(const CrowdRecorder&) = delete;
    CrowdRecorder& operator=(const CrowdRecorder&) = delete;

    // Whether setup commands wait to be recorded (on a borrowed device; a program's own device
    // runs them at once).
    bool setupPending() const;
    void recordSetup(VkCommandBuffer cmd);
    // The submission recordSetup went into has finished: its staging memory is freed.
    void setupCompleted();

    // `crowd`: laid out as the one the recorder was made for (crowd::Crowd::layoutKey), else gpu::Error.
    // Uploads what it changed since the last frame that ran (render/frame_ledger.h).
    // `samples`: the host's device samples this frame (render/driven_pass.h), for its device-driven
    // characters; GPU animation only.
    void recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const render::FrameView& view, const crowd::Crowd& crowd,
                       const render::DeviceSampleInput* samples = nullptr);
    // The device samples' fate in the slot's last frame (read after its fence).
    render::IngestTally ingestTally(std::uint32_t slot) const { return animationPass_.driven().tally(slot); }
    // Frames recorded and never submitted, found so far (render/frame_ledger.h).
    std::uint64_t framesLost() const { return ledger_.framesLost(); }
    void recordShadows(VkCommandBuffer cmd, std::uint32_t slot);
    void recordGround(VkCommandBuffer cmd, std::uint32_t slot) const;
    void recordCharacters(VkCommandBuffer cmd, std::uint32_t slot);
    void setPassObserver(gpu::PassObserver observer) { passes_ = std::move(observer); }
    const gpu::PassObserver& passObserver() const { return passes_; }
    FrameOutput output() const;

    // Between frames, with the GPU idle (the host's decision): the skinning method, culling and
    // LOD settings (the first switch to impostors bakes the atlas: setup work), shadows, animation path.
    void setMethod(skin::Method method);
    void setCull(const render::CullSettings& cull);
    const render::CullSettings& cull() const { return cull_; }
    void setShadows(bool on) { shadows_ = on; }
    bool shadows() const { return shadows_; }
    void setShadowRaster(render::ShadowRasterPath path);
    render::ShadowRasterPath shadowRaster() const { return shadowRasterPath_; }
    // The compute rasterizer of the mesh casters; null until the compute path was first taken.
    const render::ShadowRaster* computeShadowRaster() const { return shadowRaster_.get(); }
    // Whether this frame's mesh casters go through the compute rasterizer (the path asks for it and the
    // method's skinned vertices can be read by it).
    bool rastersShadowsInCompute() const;
    // With the mesh casters in compute, the impostor casters go there too (on by default); off, they are
    // drawn by the graphics pipeline over the copied map, as before (tests compare the two).
    void setImpostorShadowsInCompute(bool on) { impostorShadowsInCompute_ = on; }
    const render::ShadowMap& shadowMap() const { return shadowMap_; }
    // The shadow map's cascades, 1 to render::kMostShadowCascades (render/shadow_cascades.h).
    void setShadowCascades(std::uint32_t count);
    std::uint32_t shadowCascades() const { return shadowCascades_; }
    // The cascades' views and projections for this view (culling, the scene's uniforms and the shadow
    // pass all take them).
    render::ShadowCascades shadowCascadesOf(const render::FrameView& view) const;
    // A method or path whose bone blocks belong to others (skin::boneBlocksFor) reallocates the bones.
    void setAnimation(render::AnimationPath path);
    void setImpostorBlend(bool on) { impostorBlend_ = on; }
    bool impostorBlend() const { return impostorBlend_; }
    void setFarCrowd(bool on) { farCrowd_ = on; }
    bool farCrowd() const { return farCrowd_; }
    void setGround(bool on) { ground_ = on; }
    render::AnimationPath animation() const { return animation_; }

    std::uint32_t framesInFlight() const { return framesInFlight_; }
    // The levels drawn in the slot's last frame: read once the host has waited for it.
    render::LodCounts countsOf(std::uint32_t slot) const { return lists_.countsOf(slot); }
    // The rasterizer the impostors get (options.raster, or hardware where auto lacked what it needs).
    render::RasterMode raster() const { return raster_; }
    const render::ImpostorRaster* impostorRaster() const { return impostorRaster_.get(); }
    const render::MeshRaster* meshRaster() const { return meshRaster_.get(); }
    // Whether this frame's small meshes go through the compute rasterizer (raster compute or auto, a
    // method that skins into a buffer the pass can read).
    bool rastersMeshesInCompute() const;
    // Whether slot `slot`'s frame, recorded last, drew its small meshes in compute (the split's list is
    // this frame's then).
    bool meshesInComputeThisFrame(std::uint32_t slot) const { return meshPathOn_[slot]; }
    skin::SkinningMethod& method() { return *method_; }
    const skin::SkinningMethod& method() const { return *method_; }
    const render::GeometryPool& pool() const { return pool_; }
    const render::CrowdBuffers& buffers() const { return buffers_; }
    const render::DrawLists& drawLists() const { return lists_; }
    const render::CullPass& cullPass() const { return cullPass_; }
    const render::EventPass* eventPass() const { return eventPass_.get(); }
    std::shared_ptr<const render::ImpostorAtlas> impostorAtlas() const { return atlas_; }
    const render::CrowdShape& shape() const { return shape_; }
    // What the cull pass gets for this view and the current settings (the CPU reference takes the same).
    gpu::CullUniforms cullUniforms(const render::FrameView& view) const;
    gpu::CullUniforms cullUniforms(const render::FrameView& view, const render::ShadowCascades& cascades) const;
    // Whether level changes fade this frame: asked for, and the method draws from skinned vertices.
    bool fadesDrawn() const;
    // Device memory of the crowd's buffers and the method's resources.
    std::vector<skin::MemoryItem> memory() const;
    // The same per character of the crowd, by kind: "state" (record, motion segment, LOD state,
    // impostor-list entries, the vs baseline's draw slots (vs only); with a mesh-level cap, the cut's
    // candidate and boundary entries and tie bit; with events, each character's segment start), "bones" (the mesh slots' bone blocks, or a block per
    // character with vs, static and the CPU path: render::BoneBlocks), "mesh slots" (visible lists, draws and the
    // method's skinned vertices, sized for the mesh-level capacity), "atlas" (the impostor atlas shared
    // by all), "fixed" (geometry, clip library, shadow map, impostor quads, the cut's size histograms, the
    // event buffer and clip events).
    std::map<std::string, double> memoryPerCharacter() const;

private:
    // The impostor casters' compute pass, made on first use; null without impostors or when switched off.
    render::ImpostorShadowRaster* impostorShadowRaster();
    enum class Stage { Idle, Computed, Shadowed };
    void checkSlot(const char* call, std::uint32_t slot) const;
    void checkStage(const char* call, std::uint32_t slot, Stage needed) const;
    void drawGround(VkCommandBuffer cmd, std::uint32_t slot) const;
    // The path this frame takes: none when the method no longer reads bones; the CPU for the fixed
    // layout's one frame (it needs every character's bones, not only the visible ones).
    std::optional<render::AnimationPath> animationThisFrame() const;
    void enableImpostors();
    void updateUniforms(std::uint32_t slot, const render::FrameView& view);
    std::unique_ptr<skin::SkinningMethod> createMethod(skin::Method method) const;
    // The method and path from now on, with the bone blocks they need.
    void switchTo(skin::Method method, render::AnimationPath path);
    void useBoneBlocks(render::BoneBlocks blocks);
    // The vs baseline's per-character draws, made for it alone.
    void useCharacterDraws(bool on);

    const gpu::VulkanContext& context_;
    // The layout of the crowds this recorder draws (crowd::Crowd::layoutKey), its slots, models and the
    // impostors' prop sets (from the crowd it was made for).
    std::uint64_t layoutKey_;
    std::uint32_t slotCount_;
    std::vector<const model::SkinnedModel*> models_;
    std::vector<std::vector<std::uint32_t>> propSets_;
    render::FrameLedger ledger_;
    std::uint64_t populationVersion_ = 0;  // the crowd's population when the static ceiling last skinned
    render::TargetFormat target_;
    std::uint32_t framesInFlight_;
    render::GeometryPool pool_;
    render::CrowdBuffers buffers_;
    render::DrawLists lists_;
    render::TerrainBuffer terrain_;
    render::CullPass cullPass_;
    render::AnimationPass animationPass_;
    std::unique_ptr<render::EventPass> eventPass_;  // with events on
    std::uint32_t maxTargetDimension_;
    render::CrowdShape shape_;
    render::ShadowMap shadowMap_;
    render::GroundSunlight groundSunlight_;  // the shadow map's comparisons on the ground, per texel
    render::ScenePass scene_;
    render::CharacterDraw draw_;
    std::unique_ptr<skin::SkinningMethod> method_;
    render::ImpostorSettings impostorSettings_;
    std::shared_ptr<const void> contextOwner_;
    std::shared_ptr<const render::ImpostorAtlas> atlas_;
    std::unique_ptr<render::ImpostorRaster> impostorRaster_;  // before impostorDraw_: it reads the split
    std::unique_ptr<render::ImpostorDraw> impostorDraw_;
    std::unique_ptr<render::MeshRaster> meshRaster_;  // with raster compute or auto
    bool meshRasterGated_ = false;          // auto's automatic limit: on by the previous frame's triangles
    std::uint64_t meshRasterMinTriangles_ = 0;
    std::vector<bool> meshPathOn_;          // per slot: this frame's decision
    render::RasterMode raster_;  // in effect (auto without what it needs: hardware)
    float rasterLimitPixels_;
    std::uint32_t resolveTilePixels_;  // the rasterizers' resolve tiles (0: the whole viewport)
    render::FarCrowdSizes farSizes_;   // which impostors the far layer takes (far-crowd on)
    render::CullSettings cull_;
    render::AnimationPath animation_;
    bool shadows_;
    render::ShadowRasterPath shadowRasterPath_;
    std::uint32_t shadowCascades_ = render::kDefaultShadowCascades;
    std::unique_ptr<render::ShadowRaster> shadowRaster_;  // made when the compute path is first asked for
    // The impostor casters beside the mesh casters in compute (made when first needed; after
    // shadowRaster_, whose depth buffer it writes, so destroyed before it).
    std::unique_ptr<render::ImpostorShadowRaster> impostorShadowRaster_;
    bool impostorShadowsInCompute_ = true;
    bool impostorBlend_;
    bool farCrowd_;
    bool ground_;  // recordCharacters draws the ground behind the opaque characters
    bool sky_;     // and then the sky on every pixel left at the cleared depth
    gpu::PassObserver passes_;
    std::vector<Stage> stages_;              // per slot: how far this frame has been recorded
    std::vector<render::FrameView> views_;   // per slot: the view recordCompute was given
    // Per slot: its view's shadow cascades, computed once a frame for culling, uniforms and the shadow pass.
    std::vector<render::ShadowCascades> cascades_;
};

}  // namespace frame
