#include "frame/crowd_recorder.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>
#include <string>

#include "gpu/one_shot_commands.h"
#include "gpu/pipeline.h"
#include "gpu/setup_queue.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/impostor_prop_sets.h"

namespace frame {
namespace {

std::uint32_t checkedFramesInFlight(std::uint32_t frames) {
    if (frames == 0 || frames > 8) throw gpu::Error("frames in flight must be 1 to 8, not " + std::to_string(frames));
    return frames;
}

}  // namespace

std::uint32_t meshCapacityInEffect(const RecorderOptions& options, const crowd::Crowd& crowd) {
    return options.cull.impostors && options.meshCapacity > 0 && options.meshCapacity < crowd.size() ? options.meshCapacity
                                                                                                    : 0u;
}

std::uint32_t meshSlots(const RecorderOptions& options, const crowd::Crowd& crowd) {
    const std::uint32_t capacity = meshCapacityInEffect(options, crowd);
    return capacity > 0 ? capacity : crowd.size();
}

render::RasterMode rasterInEffect(const gpu::VulkanContext& context, const RecorderOptions& options) {
    if (options.raster == render::RasterMode::Hardware) return options.raster;
    if (context.int64Atomics) return options.raster;
    if (options.raster == render::RasterMode::Auto) return render::RasterMode::Hardware;
    throw gpu::Error("raster compute needs the features shaderInt64 and shaderBufferInt64Atomics, which " +
                         context.description.name + " lacks or the device was created without",
                     gpu::ErrorKind::Unsupported);
}

std::string viewportProblem(const VkPhysicalDeviceLimits& limits, const std::string& deviceName, render::RasterMode raster,
                            VkExtent2D extent) {
    // Called every frame by recordCompute: words are made only for a refusal.
    const auto size = [](std::uint32_t width, std::uint32_t height) {
        return std::to_string(width) + "x" + std::to_string(height);
    };
    const std::uint32_t* most = limits.maxViewportDimensions;
    if (extent.width > most[0] || extent.height > most[1])
        return "the viewport's " + size(extent.width, extent.height) + " passes " + deviceName +
               "'s maxViewportDimensions of " + size(most[0], most[1]);
    // Under auto such a viewport goes to the hardware rasterizer (ImpostorRaster::record, the mesh path's
    // gate); asked for compute, the frame cannot be drawn as asked.
    if (raster == render::RasterMode::Compute && !render::visibilityFits(limits, extent))
        return "raster compute binds a visibility buffer of " + gpu::formatBytes(render::visibilityBytes(extent)) +
               " for the " + size(extent.width, extent.height) + " viewport, over " + deviceName +
               "'s maxStorageBufferRange of " + gpu::formatBytes(limits.maxStorageBufferRange) +
               " (raster auto draws it on the hardware)";
    return {};
}

CrowdRecorder::CrowdRecorder(const gpu::VulkanContext& context, const crowd::Crowd& crowd, const RecorderOptions& options)
    : context_(context),
      layoutKey_(crowd.layoutKey()),
      slotCount_(crowd.size()),
      models_(crowd.models()),
      propSets_(render::impostorPropSets(crowd)),
      ledger_(context, options.framesInFlight),
      target_(options.target),
      framesInFlight_(checkedFramesInFlight(options.framesInFlight)),
      pool_(context, crowd.models()),
      buffers_(context, crowd, options.framesInFlight, skin::boneBlocksFor(options.method, options.animation),
               meshSlots(options, crowd)),
      lists_(context, pool_, buffers_, options.framesInFlight, meshCapacityInEffect(options, crowd),
             options.method == skin::Method::VertexShader),
      terrain_(context, crowd, options.terrainSamples, options.framesInFlight),
      cullPass_(context, pool_, buffers_, lists_, options.framesInFlight),
      animationPass_(context, crowd, buffers_, lists_, terrain_, options.framesInFlight),
      eventPass_(options.events ? std::make_unique<render::EventPass>(context, crowd, animationPass_, buffers_, lists_,
                                                                      terrain_, options.framesInFlight,
                                                                      options.eventCapacity)
                                : nullptr),
      maxTargetDimension_(options.maxTargetDimension),
      shape_{crowd.center(), crowd.radius(), crowd.tallestHeight(), crowd.terrain().lowest()},
      shadowMap_(context, options.shadowMapSize),
      groundSunlight_(context, shadowMap_),
      scene_(context, options.framesInFlight, pool_, shadowMap_, groundSunlight_, terrain_, options.target,
             {!options.pointSampledGround, !options.perPixelGroundShadows}),
      draw_(context, pool_, buffers_, lists_, scene_.setLayout(), options.target),
      method_(createMethod(options.method)),
      impostorSettings_(options.impostorSettings),
      contextOwner_(options.contextOwner),
      atlas_(options.atlas),
      raster_(rasterInEffect(context, options)),
      rasterLimitPixels_(options.raster == render::RasterMode::Compute ? std::numeric_limits<float>::infinity()
                                                                      : options.rasterLimitPixels),
      resolveTilePixels_(options.resolveTilePixels),
      farSizes_{options.farCrowdPixels, options.farCrowdSplatPixels},
      cull_(options.cull),
      animation_(options.animation),
      shadows_(options.shadows),
      shadowRasterPath_(options.shadowRaster),
      impostorBlend_(options.impostorBlend),
      farCrowd_(options.farCrowd),
      ground_(options.ground),
      sky_(options.sky),
      stages_(options.framesInFlight, Stage::Idle),
      views_(options.framesInFlight),
      cascades_(options.framesInFlight) {
    // The shadow map and the ground's sunlight are bound even while shadows are off: a valid layout from
    // setup on (every frame that draws shadows leaves them so too), never from a frame that may be dropped.
    gpu::runOneShot(context, [map = &shadowMap_, sunlight = &groundSunlight_](VkCommandBuffer cmd) {
        map->clear(cmd);
        sunlight->recordAllLit(cmd);
    });
    if (cull_.impostors) enableImpostors();
    setShadowRaster(options.shadowRaster);
    setShadowCascades(options.shadowCascades);
    // Meshes in compute: every one it can take under compute, the small ones under auto (none while
    // auto's limit is 0).
    const bool automatic = options.meshRasterLimitPixels < 0.0f;
    const float meshLimit = raster_ == render::RasterMode::Compute ? std::numeric_limits<float>::infinity()
                            : raster_ == render::RasterMode::Auto
                                ? (automatic ? render::kAutoMeshRasterLimitPixels : options.meshRasterLimitPixels)
                                : 0.0f;
    meshRasterGated_ = raster_ == render::RasterMode::Auto && automatic;
    meshRasterMinTriangles_ = options.meshRasterMinTriangles;
    meshPathOn_.assign(options.framesInFlight, false);
    if (meshLimit > 0.0f)
        meshRaster_ = std::make_unique<render::MeshRaster>(context_, pool_, buffers_, lists_, scene_.setLayout(),
                                                           target_, options.framesInFlight, meshLimit,
                                                           resolveTilePixels_);
}

void CrowdRecorder::setShadowRaster(render::ShadowRasterPath path) {
    // A map whose depths pass one storage binding stays with the hardware pass (rastersShadowsInCompute).
    if (path == render::ShadowRasterPath::Compute && !shadowRaster_ &&
        render::ShadowRaster::fits(context_.properties.limits, shadowMap_.size()))
        shadowRaster_ = std::make_unique<render::ShadowRaster>(context_, pool_, lists_, shadowMap_);
    shadowRasterPath_ = path;
}

void CrowdRecorder::setShadowCascades(std::uint32_t count) {
    if (count < 1 || count > render::kMostShadowCascades)
        throw gpu::Error("shadow cascades: " + std::to_string(count) + " is not 1 to " +
                         std::to_string(render::kMostShadowCascades));
    shadowCascades_ = count;
}

render::ShadowCascades CrowdRecorder::shadowCascadesOf(const render::FrameView& view) const {
    return render::shadowCascades(render::cameraOf(view), render::aspectOf(view), shape_, render::lightDirection(),
                                  shadowCascades_, shadowMap_.size());
}

bool CrowdRecorder::rastersShadowsInCompute() const {
    return shadowRasterPath_ == render::ShadowRasterPath::Compute && shadowRaster_ &&
           method_->drawInput() == render::DrawInput::SkinnedVertices && shadowRaster_->canRead(method_->skinnedVertices());
}

CrowdRecorder::~CrowdRecorder() = default;

std::unique_ptr<skin::SkinningMethod> CrowdRecorder::createMethod(skin::Method method) const {
    return skin::createSkinningMethod(method, {context_, pool_, buffers_, lists_, maxTargetDimension_});
}

bool CrowdRecorder::setupPending() const {
    const gpu::SetupQueue* setup = context_.deferredSetup();
    return setup && setup->pending();
}

bool CrowdRecorder::rastersMeshesInCompute() const {
    return meshRaster_ && method_->drawInput() == render::DrawInput::SkinnedVertices &&
           meshRaster_->canRead(method_->skinnedVertices());
}

void CrowdRecorder::recordSetup(VkCommandBuffer cmd) {
    if (gpu::SetupQueue* setup = context_.deferredSetup()) setup->recordInto(cmd);
}

void CrowdRecorder::setupCompleted() {
    if (gpu::SetupQueue* setup = context_.deferredSetup()) setup->releaseRecorded();
}

void CrowdRecorder::checkSlot(const char* call, std::uint32_t slot) const {
    if (slot >= framesInFlight_)
        throw gpu::Error(std::string(call) + ": frame slot " + std::to_string(slot) + " out of range (the renderer has " +
                         std::to_string(framesInFlight_) + " frames in flight)");
}

void CrowdRecorder::checkStage(const char* call, std::uint32_t slot, Stage needed) const {
    checkSlot(call, slot);
    if (stages_[slot] < needed)
        throw gpu::Error(std::string(call) + ": slot " + std::to_string(slot) +
                         " has no recordCompute for this frame (record compute, then shadows, then draw)",
                         gpu::ErrorKind::WrongOrder);
}

void CrowdRecorder::recordCompute(VkCommandBuffer cmd, std::uint32_t slot, const render::FrameView& view,
                                  const crowd::Crowd& crowd, const render::DeviceSampleInput* samples) {
    checkSlot("recordCompute", slot);
    if (crowd.layoutKey() != layoutKey_ || crowd.size() != slotCount_)
        throw gpu::Error("recordCompute: the crowd given is not laid out as the one the renderer was made for (" +
                         std::to_string(crowd.size()) + " slots, the renderer's " + std::to_string(slotCount_) +
                         "; the same models, each slot's the same)");
    if (setupPending())
        throw gpu::Error("recordCompute: setup work waits to be recorded (call recordSetup and submit it first)",
                         gpu::ErrorKind::WrongOrder);
    if (!render::isPerspectiveView(view))
        throw gpu::Error("recordCompute: the view or projection matrix is not a finite perspective view");
    if (view.viewport.extent.width == 0 || view.viewport.extent.height == 0)
        throw gpu::Error("recordCompute: the viewport is empty");
    if (const std::string problem = viewportProblem(context_.properties.limits, context_.description.name, raster_,
                                                    view.viewport.extent);
        !problem.empty())
        throw gpu::Error("recordCompute: " + problem,
                         render::visibilityFits(context_.properties.limits, view.viewport.extent)
                             ? gpu::ErrorKind::InvalidArgument
                             : gpu::ErrorKind::Unsupported);
    if (samples && animationThisFrame() != render::AnimationPath::Gpu)
        throw gpu::Error("recordCompute: device samples need the GPU animation path (the CPU never sees them)");
    if (samples) animationPass_.checkDeviceSamples(*samples);  // before anything is recorded
    views_[slot] = view;
    // Where the crowd stands now (the population changes; the host's world bounds, when set, do not),
    // above the terrain's lowest point.
    shape_ = {crowd.center(), crowd.radius(), crowd.tallestHeight(), crowd.terrain().lowest()};
    cascades_[slot] = shadowCascadesOf(view);
    // What changed since the last frame (or since a frame that never ran): render/frame_ledger.h.
    terrain_.check(crowd);
    const render::FrameLedger::Uploads uploads = ledger_.begin(cmd, slot, crowd.id(), crowd.sealChanges());
    const std::uint64_t since = uploads.since;
    terrain_.recordUpload(cmd, slot, crowd, uploads.resend);
    // The static ceiling skins everyone once: again when someone came or went.
    if (crowd.population().version() != populationVersion_) method_->invalidateSkinning();
    populationVersion_ = crowd.population().version();

    // The CPU path samples every character's clips here; the GPU path moves them in its passes. The
    // segments and identities go up first on either (the CPU path's records take the identities).
    animationPass_.recordSegmentUpload(cmd, slot, crowd, since);
    if (samples) animationPass_.recordDeviceSamples(cmd, slot, crowd, *samples, view.time);
    const std::optional<render::AnimationPath> path = animationThisFrame();
    if (path == render::AnimationPath::Cpu)
        crowd.animate(view.time, buffers_.boneStaging(slot), buffers_.boneOffsets(), buffers_.mutableRecords());
    else if (cull_.mode == render::CullMode::Cpu)
        buffers_.updateRecords(crowd, view.time);  // the CPU reference culls from CPU-side records

    if (path == render::AnimationPath::Cpu) {
        buffers_.recordCpuAnimationUpload(cmd, slot);
        gpu::passDone(passes_, cmd, "upload");
    } else if (path == render::AnimationPath::Gpu) {
        buffers_.recordRecordsUploadIfStale(cmd, slot);  // after bone blocks left the mesh slots
        animationPass_.recordMotion(cmd, crowd, view.time);
        gpu::passDone(passes_, cmd, "motion");
    }
    const bool perCharacterDraws = method_->drawInput() == render::DrawInput::BindPosePerCharacter;
    cullPass_.record(cmd, slot, cullUniforms(view, cascades_[slot]), cull_.mode, method_->fixedLayout(), perCharacterDraws);
    gpu::passDone(passes_, cmd, "cull");
    if (eventPass_) {
        // Culling said who is in view.
        eventPass_->record(cmd, slot, crowd, since, view.time);
        gpu::passDone(passes_, cmd, "events");
    }
    if (path == render::AnimationPath::Gpu) {
        animationPass_.recordPalettes(cmd);
        gpu::passDone(passes_, cmd, "palette");
    }
    method_->recordSkinning(cmd, passes_);
    if (impostorRaster_) {
        // Before the impostor draws: the colour draw's count is what the rasterizer leaves to it.
        const render::Camera camera = render::cameraOf(view);
        impostorRaster_->record(cmd, slot, view.projection * view.view, camera.eye, view.viewport.extent, impostorBlend_,
                                 farCrowd_);
    }
    // Auto's automatic limit: the mesh path when the hardware rasterizer was this slot's wall last time
    // (its frame's counts, read back: the host waited for the slot).
    meshPathOn_[slot] = rastersMeshesInCompute() && render::visibilityFits(context_.properties.limits, view.viewport.extent) &&
                        (!meshRasterGated_ || lists_.countsOf(slot).totalTriangles() >= meshRasterMinTriangles_);
    if (meshPathOn_[slot]) {
        // After skinning, before the colour draw: the small meshes leave the colour list for compute.
        const render::Camera camera = render::cameraOf(view);
        const float pixelsPerUnit =
            static_cast<float>(view.viewport.extent.height) / (2.0f * std::tan(camera.verticalFov * 0.5f));
        meshRaster_->record(cmd, slot, method_->skinnedVertices(), view.projection * view.view, camera.eye,
                            pixelsPerUnit, view.viewport.extent);
    }
    if (impostorRaster_ || meshPathOn_[slot]) gpu::passDone(passes_, cmd, "raster");
    if (impostorDraw_) impostorDraw_->recordDraws(cmd);
    updateUniforms(slot, view);
    stages_[slot] = Stage::Computed;
}

std::optional<render::AnimationPath> CrowdRecorder::animationThisFrame() const {
    if (!method_->needsAnimation()) return std::nullopt;
    return method_->fixedLayout() ? render::AnimationPath::Cpu : animation_;
}

gpu::CullUniforms CrowdRecorder::cullUniforms(const render::FrameView& view) const {
    return cullUniforms(view, shadowCascadesOf(view));
}

gpu::CullUniforms CrowdRecorder::cullUniforms(const render::FrameView& view, const render::ShadowCascades& cascades) const {
    const render::Camera camera = render::cameraOf(view);
    gpu::CullUniforms uniforms = render::makeCullUniforms(
        cull_, view.projection * view.view, camera.eye, camera.verticalFov, view.viewport.extent.height, slotCount_,
        lists_.bucketCount(), context_.properties.limits.maxComputeWorkGroupCount[0]);
    // With shadows, characters out of view whose shadows may fall into it are kept (and skinned) too,
    // those outside the shadow map's volume are not, and each caster's level comes from its size there.
    render::setShadowUniforms(uniforms, cull_, shadows_, cascades, shadowMap_.size(), render::lightDirection());
    uniforms.limits.z = lists_.meshCapacity();
    if (!fadesDrawn()) uniforms.fade.x = 0u;
    return uniforms;
}

bool CrowdRecorder::fadesDrawn() const {
    // Fades between mesh levels are morphs made while skinning, and fades into impostors dither a
    // list of their own: the vertex-shader methods draw from lists without it (one command per
    // character, one instanced draw per bucket), and the static ceiling skins once, so neither fades.
    return cull_.lodFade && method_->drawInput() == render::DrawInput::SkinnedVertices && !method_->fixedLayout();
}

void CrowdRecorder::updateUniforms(std::uint32_t slot, const render::FrameView& view) {
    const render::Camera camera = render::cameraOf(view);
    const render::ShadowCascades& cascades = cascades_[slot];
    for (std::uint32_t c = 0; c < cascades.count; ++c)
        scene_.updateLight(slot, c, render::makeSceneUniforms(cascades.mapClip(c), 0.0f));
    gpu::SceneUniforms scene = render::makeSceneUniforms(view.projection * view.view, 0.5f / (camera.farPlane + 1.0f),
                                                         cascades, shadows_, shadowMap_.size());
    scene.shadow.w = static_cast<float>(groundSunlight_.firstLevel(view.viewport.extent));
    scene_.update(slot, scene);
}

void CrowdRecorder::recordShadows(VkCommandBuffer cmd, std::uint32_t slot) {
    checkStage("recordShadows", slot, Stage::Computed);
    if (!shadows_) return;
    // The same draws, skinned vertices and methods as the colour pass, seen from the light.
    const render::Camera camera = render::cameraOf(views_[slot]);
    const bool compute = rastersShadowsInCompute();
    const render::ShadowCascades& cascades = cascades_[slot];
    const render::ScenePush push{glm::vec4(camera.eye, 1.0f), glm::vec4(0.0f)};
    // Impostor casters in compute beside the mesh casters (render/impostor_shadow_raster.h).
    const bool impostorsInCompute = compute && impostorShadowRaster();
    if (compute) {
        shadowRaster_->rasterize(cmd, method_->skinnedVertices(), cascades);
        if (impostorsInCompute) impostorShadowRaster_->record(cmd, cascades, impostorBlend_);
        shadowRaster_->pack(cmd);
        shadowMap_.copyFrom(cmd, shadowRaster_->mapTexels());
        if (impostorDraw_ && !impostorsInCompute)
            shadowMap_.beginRenderingOver(cmd);
        else
            shadowMap_.copyDone(cmd);  // no casters left to draw: no rendering pass at all
    } else {
        shadowMap_.beginRendering(cmd);
        // Every caster into every cascade's square: the scissor and the cascade's clip space keep what falls there.
        for (std::uint32_t c = 0; c < cascades.count; ++c) {
            const VkRect2D square = cascades.texels(c, shadowMap_.size());
            vkCmdSetScissor(cmd, 0, 1, &square);
            draw_.record(cmd, method_->drawInput(), method_->skinnedVertices(), scene_.lightSet(slot, c), push,
                         render::CharacterDraw::Target::ShadowMap);
        }
    }
    // Impostor-level casters on the hardware path: a quad facing the light each, cut by the atlas's coverage.
    if (impostorDraw_ && !impostorsInCompute) {
        for (std::uint32_t c = 0; c < cascades.count; ++c) {
            const VkRect2D square = cascades.texels(c, shadowMap_.size());
            vkCmdSetScissor(cmd, 0, 1, &square);
            impostorDraw_->recordShadows(cmd, scene_.lightSet(slot, c), push, impostorBlend_);
        }
    }
    if (!compute || (impostorDraw_ && !impostorsInCompute)) shadowMap_.endRendering(cmd);
    // The ground's sunlight from the finished map, in compute, for the ground's one fetch a pixel.
    groundSunlight_.record(cmd, cascades, render::kShadowDepthBias, 1.0f / static_cast<float>(shadowMap_.size()),
                           groundSunlight_.firstLevel(views_[slot].viewport.extent));
    stages_[slot] = Stage::Shadowed;
    gpu::passDone(passes_, cmd, "shadow");
}

render::ImpostorShadowRaster* CrowdRecorder::impostorShadowRaster() {
    if (!impostorDraw_ || !atlas_ || !impostorShadowsInCompute_) return nullptr;
    if (!impostorShadowRaster_)
        impostorShadowRaster_ = std::make_unique<render::ImpostorShadowRaster>(
            context_, buffers_, lists_, *atlas_, shadowRaster_->depthBits(), shadowMap_.size());
    return impostorShadowRaster_.get();
}

void CrowdRecorder::recordGround(VkCommandBuffer cmd, std::uint32_t slot) const {
    checkStage("recordGround", slot, Stage::Computed);
    if (ground_)
        throw gpu::Error("recordGround: this renderer draws the ground in recordCharacters (its ground setting is on)",
                         gpu::ErrorKind::WrongOrder);
    drawGround(cmd, slot);
}

void CrowdRecorder::drawGround(VkCommandBuffer cmd, std::uint32_t slot) const {
    const render::FrameView& view = views_[slot];
    const render::Camera camera = render::cameraOf(view);
    gpu::setViewportAndScissor(cmd, view.viewport);
    const render::ScenePush push{glm::vec4(camera.eye, 1.0f),
                                 glm::vec4(shape_.center.x, 0.0f, shape_.center.z, camera.farPlane)};
    scene_.recordGround(cmd, slot, push, terrain_.grid());
}

void CrowdRecorder::recordCharacters(VkCommandBuffer cmd, std::uint32_t slot) {
    checkStage("recordCharacters", slot, Stage::Computed);
    if (shadows_ && stages_[slot] != Stage::Shadowed)
        throw gpu::Error("recordCharacters: slot " + std::to_string(slot) +
                         " has shadows on but no recordShadows for this frame (record it before the colour pass)",
                         gpu::ErrorKind::WrongOrder);
    const render::FrameView& view = views_[slot];
    const render::Camera camera = render::cameraOf(view);
    gpu::setViewportAndScissor(cmd, view.viewport);
    const render::ScenePush push{glm::vec4(camera.eye, 1.0f),
                                 glm::vec4(shape_.center.x, 0.0f, shape_.center.z, camera.farPlane)};
    draw_.record(cmd, method_->drawInput(), method_->skinnedVertices(), scene_.set(slot), push,
                 render::CharacterDraw::Target::Colour, fadesDrawn());
    // Far characters (and those over the mesh-level cap): after the meshes, depth-tested against them.
    if (impostorDraw_) impostorDraw_->record(cmd, scene_.set(slot), push, impostorBlend_);
    // The compute-rasterized impostors, merged with all of the above by their depth.
    if (impostorRaster_) impostorRaster_->recordResolve(cmd, slot, scene_.set(slot), camera.eye, view.viewport, impostorBlend_);
    if (meshPathOn_[slot]) meshRaster_->recordResolve(cmd, slot, scene_.set(slot), camera.eye, view.viewport);
    // The ground after every opaque character, before the one blended layer: the depth test rejects it
    // under the characters before it is shaded (a full-screen fragment pass costs the H100's graphics
    // slice about 0.3 ms at 1080p; drawn first, its pixels under the characters were shaded for nothing).
    if (ground_) drawGround(cmd, slot);
    // The sky where nothing opaque is, before the layer that blends over it (the far crowd stands on it).
    if (sky_) scene_.recordSky(cmd, slot);
    // The far crowd's averaged layer, blended over everything opaque that is behind it.
    if (impostorRaster_) impostorRaster_->recordFarResolve(cmd, slot, scene_.set(slot), camera.eye, view.viewport);
    stages_[slot] = Stage::Idle;
}

FrameOutput CrowdRecorder::output() const {
    FrameOutput out;
    out.input = method_->drawInput();
    out.vertices = method_->skinnedVertices();
    out.indices = pool_.indices().buffer;
    out.draws = lists_.draws().buffer;
    out.drawCount = lists_.totals().buffer;
    out.drawCountOffset = offsetof(gpu::DrawTotals, drawCount);
    out.maxDraws = lists_.drawCapacity();
    out.fadingDrawsOffset = VkDeviceSize{lists_.fadingDrawBase()} * sizeof(gpu::DrawIndexedCommand);
    out.fadingCountOffset = offsetof(gpu::DrawTotals, fading);
    out.characters = buffers_.characters().buffer;
    if (eventPass_) {
        out.events = eventPass_->events().buffer;
        out.eventCapacity = eventPass_->capacity();
    }
    return out;
}

void CrowdRecorder::setCull(const render::CullSettings& cull) {
    cull_ = cull;
    if (cull_.impostors) enableImpostors();
}

void CrowdRecorder::enableImpostors() {
    if (impostorDraw_) return;
    if (!atlas_) {
        // The bake reads the materials and textures through a scene set: slot 0's (the same in every slot).
        scene_.update(0, render::makeSceneUniforms(glm::mat4(1.0f), 0.0f));
        // The atlas keeps the context it was made with alive: another recorder may share it.
        atlas_ = std::shared_ptr<const render::ImpostorAtlas>(
            new render::ImpostorAtlas(context_, pool_, models_, propSets_,
                                      scene_.setLayout(), scene_.set(0), impostorSettings_),
            [owner = contextOwner_](const render::ImpostorAtlas* atlas) { delete atlas; });
    } else if (atlas_->plan().modelCount() != pool_.modelCount()) {
        throw gpu::Error("impostors: the atlas given was baked for other models");
    }
    render::ImpostorSplitBuffers split;
    if (raster_ != render::RasterMode::Hardware) {
        impostorRaster_ = std::make_unique<render::ImpostorRaster>(context_, pool_, buffers_, lists_, *atlas_,
                                                                   scene_.setLayout(), target_, framesInFlight_,
                                                                   rasterLimitPixels_, resolveTilePixels_,
                                                                   farSizes_);
        split = {&impostorRaster_->split(), &impostorRaster_->hardwareList()};
    }
    impostorDraw_ = std::make_unique<render::ImpostorDraw>(context_, pool_, buffers_, lists_, *atlas_, scene_.setLayout(),
                                                           target_, split);
}

void CrowdRecorder::setMethod(skin::Method method) { switchTo(method, animation_); }

void CrowdRecorder::setAnimation(render::AnimationPath path) { switchTo(method_->method(), path); }

void CrowdRecorder::switchTo(skin::Method method, render::AnimationPath path) {
    const skin::Method previous = method_->method();
    const render::BoneBlocks blocks = skin::boneBlocksFor(method, path);
    if (method != previous || blocks != buffers_.boneBlocks()) {
        if (shadowRaster_) shadowRaster_->forgetVertices();  // the next method's buffer may reuse the handle
        if (meshRaster_) meshRaster_->forgetVertices();
        method_.reset();  // its buffers go before the next method's come
        try {
            useBoneBlocks(blocks);
            useCharacterDraws(method == skin::Method::VertexShader);
            method_ = createMethod(method);
        } catch (...) {
            // Refused (the bones or the method do not fit): the renderer stays as it was.
            useBoneBlocks(skin::boneBlocksFor(previous, animation_));
            useCharacterDraws(previous == skin::Method::VertexShader);
            method_ = createMethod(previous);
            throw;
        }
    }
    animation_ = path;
}

void CrowdRecorder::useCharacterDraws(bool on) {
    if (on == lists_.hasCharacterDraws()) return;
    lists_.setCharacterDraws(on);
    cullPass_.rebindCharacterDraws();
}

void CrowdRecorder::useBoneBlocks(render::BoneBlocks blocks) {
    if (blocks == buffers_.boneBlocks()) return;
    buffers_.setBoneBlocks(blocks);
    animationPass_.rebindBones(buffers_);
    draw_.rebindBones();
}

std::vector<skin::MemoryItem> CrowdRecorder::memory() const {
    std::vector<skin::MemoryItem> items = {{"geometry pool (vertices, LOD indices, textures)", pool_.bytes()},
                                           {"character records and bone matrices", buffers_.deviceBytes()},
                                           {"clip library (GPU animation)", animationPass_.libraryBytes()},
                                           {"motion segments (GPU animation)", animationPass_.segmentBytes()},
                                           {"culling lists and draw commands", lists_.bytes()},
                                           {"shadow map", shadowMap_.bytes()},
                                           {"ground sunlight (shadow map on the ground)", groundSunlight_.bytes()},
                                           {"driven keys, counts and their uploads", animationPass_.driven().bytes()},
                                           {"terrain", terrain_.buffer().size}};
    if (shadowRaster_) items.push_back({"shadow map depth (compute raster)", shadowRaster_->bytes()});
    if (eventPass_) items.push_back({"event buffer, clip events, previous segments", eventPass_->bytes()});
    if (atlas_) items.push_back({"impostor atlas", atlas_->bytes()});
    if (impostorDraw_) items.push_back({"impostor quad indices and draws", impostorDraw_->bytes()});
    if (impostorRaster_) items.push_back({"visibility buffers and raster split", impostorRaster_->bytes()});
    if (meshRaster_) items.push_back({"mesh visibility buffers and raster list", meshRaster_->bytes()});
    for (const skin::MemoryItem& item : method_->memory()) items.push_back(item);
    return items;
}

std::map<std::string, double> CrowdRecorder::memoryPerCharacter() const {
    const double n = std::max(slotCount_, 1u);
    // The mesh cut's lists and tie bits grow with the crowd; its histograms do not.
    const render::MeshCutSizes cut = render::meshCutSizes(slotCount_, lists_.meshCapacity());
    const double state = static_cast<double>(buffers_.characters().size + animationPass_.segmentBytes() +
                                             lists_.lodState().size + lists_.shadowStates().size +
                                             lists_.impostorList().size +
                                             lists_.characterDraws().size + cut.candidates + cut.boundary +
                                             cut.tieBits + (eventPass_ ? eventPass_->characterBytes() : 0u) +
                                             animationPass_.driven().bytes());
    double meshSlots = static_cast<double>(lists_.visible().size + lists_.draws().size);
    for (const skin::MemoryItem& item : method_->memory()) meshSlots += static_cast<double>(item.bytes);
    const double fixed = static_cast<double>(pool_.bytes() + animationPass_.libraryBytes() + shadowMap_.bytes() +
                                             terrain_.buffer().size +
                                             groundSunlight_.bytes() +
                                             (shadowRaster_ ? shadowRaster_->bytes() : 0u) +
                                             (impostorDraw_ ? impostorDraw_->bytes() : 0u) + cut.histograms +
                                             (eventPass_ ? eventPass_->bytes() - eventPass_->characterBytes() : 0u));
    return {{"state", state / n},
            {"bones", static_cast<double>(buffers_.bones().size) / n},
            {"mesh slots", meshSlots / n},
            {"atlas", atlas_ ? static_cast<double>(atlas_->bytes()) / n : 0.0},
            {"fixed", fixed / n}};
}

}  // namespace frame
