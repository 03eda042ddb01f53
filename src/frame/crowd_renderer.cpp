#include "frame/crowd_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "gpu/barriers.h"
#include "gpu/pipeline.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace frame {
namespace {

double nowMs() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

float aspectOf(VkExtent2D extent) { return static_cast<float>(extent.width) / static_cast<float>(extent.height); }

// The cap applies only when impostors are there from the start to take the characters beyond it.
std::uint32_t meshCapacityOf(const RendererOptions& options, const crowd::Crowd& crowd) {
    return options.cull.impostors && options.meshCapacity > 0 && options.meshCapacity < crowd.size() ? options.meshCapacity
                                                                                                    : 0u;
}

}  // namespace

CrowdRenderer::CrowdRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd,
                             const RendererOptions& options)
    : context_(context),
      crowd_(crowd),
      pool_(context, crowd.models()),
      buffers_(context, crowd, options.framesInFlight),
      lists_(context, pool_, buffers_, options.framesInFlight, meshCapacityOf(options, crowd)),
      cullPass_(context, pool_, buffers_, lists_, options.framesInFlight),
      animationPass_(context, crowd, buffers_, lists_, options.framesInFlight),
      target_(std::make_unique<render::RenderTarget>(context, options.size)),
      maxTargetDimension_(options.maxTargetDimension),
      shape_{crowd.center(), crowd.radius(), crowd.tallestHeight()},
      shadowMap_(context, options.shadowMapSize),
      scene_(context, options.framesInFlight, pool_, shadowMap_),
      draw_(context, pool_, buffers_, lists_, scene_.setLayout()),
      timer_(context, options.framesInFlight, options.passClock),
      method_(createMethod(options.method)),
      impostorSettings_(options.impostorSettings),
      atlas_(options.atlas),
      cull_(options.cull),
      animation_(options.animation),
      shadows_(options.shadows),
      frames_(options.framesInFlight) {
    camera = render::frameCrowd(shape_.center, shape_.radius, shape_.characterHeight, aspectOf(options.size));
    for (Frame& frame : frames_) {
        VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocate.commandPool = context.commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(context.device, &allocate, &frame.cmd));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &frame.fence));
    }
    if (cull_.impostors) enableImpostors();
}

CrowdRenderer::~CrowdRenderer() {
    vkDeviceWaitIdle(context_.device);
    for (Frame& frame : frames_) {
        vkDestroyFence(context_.device, frame.fence, nullptr);
        vkFreeCommandBuffers(context_.device, context_.commandPool, 1, &frame.cmd);
    }
}

std::unique_ptr<skin::SkinningMethod> CrowdRenderer::createMethod(skin::Method method) const {
    return skin::createSkinningMethod(method, {context_, pool_, buffers_, lists_, maxTargetDimension_});
}

void CrowdRenderer::renderFrame(float time, const PresentHooks* hooks) {
    const auto slot = static_cast<std::uint32_t>(frameIndex_++ % frames_.size());
    Frame& frame = frames_[slot];
    const double start = nowMs();
    collect(frame, slot);  // the slot's previous frame must be done before its buffers are reused
    frame.stats = {};
    frame.stats.intervalMs = lastFrameStart_ < 0.0 ? 0.0 : start - lastFrameStart_;
    lastFrameStart_ = start;

    // 1. Motion: new segments for the characters whose plan ran out (events, not every character).
    const double planStart = nowMs();
    crowd_.advanceTo(time);
    // 2. The CPU path samples every character's clips here; the GPU path moves them in its passes.
    const double animateStart = nowMs();
    const std::optional<render::AnimationPath> path = animationThisFrame();
    if (path == render::AnimationPath::Cpu)
        crowd_.animate(time, buffers_.boneStaging(slot), buffers_.boneOffsets(), buffers_.mutableRecords());
    else if (cull_.mode == render::CullMode::Cpu)
        buffers_.updateRecords(crowd_, time);  // the CPU reference culls from CPU-side records
    const double recordStart = nowMs();
    frame.stats.planMs = animateStart - planStart;
    frame.stats.animateMs = path == render::AnimationPath::Cpu ? recordStart - animateStart : 0.0;

    // 3-8. Upload or motion, cull, palettes, skin, draw, timestamps: one command buffer, one submit.
    VK_CHECK(vkResetCommandBuffer(frame.cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(frame.cmd, &begin));
    recordFrame(frame.cmd, slot, time, path.value_or(render::AnimationPath::Cpu), hooks);
    VK_CHECK(vkEndCommandBuffer(frame.cmd));
    submit(frame, hooks);
    frame.stats.recordMs = nowMs() - recordStart;
}

std::optional<render::AnimationPath> CrowdRenderer::animationThisFrame() const {
    if (!method_->needsAnimation()) return std::nullopt;
    return method_->fixedLayout() ? render::AnimationPath::Cpu : animation_;
}

void CrowdRenderer::recordFrame(VkCommandBuffer cmd, std::uint32_t slot, float time, render::AnimationPath path,
                                const PresentHooks* hooks) {
    timer_.begin(cmd, slot);
    const bool animates = method_->needsAnimation();
    if (animates && path == render::AnimationPath::Cpu) {
        buffers_.recordCpuAnimationUpload(cmd, slot);
        timer_.mark(cmd, "upload");
    } else if (animates) {
        animationPass_.recordMotion(cmd, slot, time);
        timer_.mark(cmd, "motion");
    }
    recordCulling(cmd, slot);
    timer_.mark(cmd, "cull");
    if (animates && path == render::AnimationPath::Gpu) {
        animationPass_.recordPalettes(cmd);
        timer_.mark(cmd, "palette");
    }
    method_->recordSkinning(cmd, timer_);
    if (impostorDraw_) impostorDraw_->recordDraws(cmd);
    const glm::mat4 light = lightViewProjection();  // the shadow pass draws with it, the scene samples with it
    recordShadows(cmd, slot, light);
    recordScene(cmd, slot, light);
    timer_.mark(cmd, "draw");
    if (hooks && hooks->recordAfterScene) hooks->recordAfterScene(cmd, target_->colorImage(), target_->extent());
}

gpu::CullUniforms CrowdRenderer::cullUniforms() const {
    const VkExtent2D extent = target_->extent();
    gpu::CullUniforms uniforms = render::makeCullUniforms(
        cull_, camera.viewProjection(aspectOf(extent)), camera.eye, camera.verticalFov, extent.height, crowd_.size(),
        lists_.bucketCount(), context_.properties.limits.maxComputeWorkGroupCount[0]);
    // With shadows, characters out of view whose shadows may fall into it are kept (and skinned) too.
    uniforms.limits.y = shadows_ ? 1u : 0u;
    uniforms.light = glm::vec4(render::lightDirection(), 0.0f);
    uniforms.limits.z = lists_.meshCapacity();
    return uniforms;
}

void CrowdRenderer::recordCulling(VkCommandBuffer cmd, std::uint32_t slot) {
    const bool perCharacterDraws = method_->drawInput() == render::DrawInput::BindPosePerCharacter;
    cullPass_.record(cmd, slot, cullUniforms(), cull_.mode, method_->fixedLayout(), perCharacterDraws);
}

glm::mat4 CrowdRenderer::lightViewProjection() const {
    return render::lightViewProjection(camera, aspectOf(target_->extent()), shape_, render::lightDirection());
}

void CrowdRenderer::recordShadows(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& lightViewProjection) {
    if (!shadows_) {
        if (!shadowMapReady_) shadowMap_.clear(cmd);  // sampled by no one, but bound: a valid layout
        shadowMapReady_ = true;
        return;
    }
    // The same draws, skinned vertices and methods as the colour pass, seen from the light.
    scene_.updateLight(slot, render::makeSceneUniforms(lightViewProjection, pool_.palette(), pool_.texturedMaterials(),
                                                       0.0f));
    shadowMap_.beginRendering(cmd);
    const render::ScenePush push{glm::vec4(camera.eye, 1.0f), glm::vec4(0.0f)};
    draw_.record(cmd, method_->drawInput(), method_->skinnedVertices(), scene_.lightSet(slot), push,
                 render::CharacterDraw::Target::ShadowMap);
    shadowMap_.endRendering(cmd);
    shadowMapReady_ = true;
    timer_.mark(cmd, "shadow");
}

void CrowdRenderer::recordScene(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& lightViewProjection) {
    scene_.update(slot, render::makeSceneUniforms(camera.viewProjection(aspectOf(target_->extent())), pool_.palette(),
                                                  pool_.texturedMaterials(), 0.5f / (camera.farPlane + 1.0f),
                                                  lightViewProjection, shadows_, shadowMap_.size()));
    const float clear[4] = {render::kSkyColor.r, render::kSkyColor.g, render::kSkyColor.b, 1.0f};
    target_->beginRendering(cmd, clear);
    gpu::setViewportAndScissor(cmd, target_->extent());
    const render::ScenePush push{glm::vec4(camera.eye, 1.0f),
                                 glm::vec4(shape_.center.x, 0.0f, shape_.center.z, camera.farPlane)};
    scene_.recordGround(cmd, slot, push);
    draw_.record(cmd, method_->drawInput(), method_->skinnedVertices(), scene_.set(slot), push);
    // Far characters (and those over the mesh-level cap): after the meshes, depth-tested against them.
    if (impostorDraw_) impostorDraw_->record(cmd, scene_.set(slot), push);
    target_->endRendering(cmd);
}

void CrowdRenderer::setCull(const render::CullSettings& cull) {
    cull_ = cull;
    if (cull_.impostors) enableImpostors();
}

void CrowdRenderer::enableImpostors() {
    if (impostorDraw_) return;
    finish();
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    if (!atlas_) {
        // The bake reads the palette and textures through a scene set: slot 0's, idle now.
        scene_.update(0, render::makeSceneUniforms(glm::mat4(1.0f), pool_.palette(), pool_.texturedMaterials(), 0.0f));
        atlas_ = std::make_shared<render::ImpostorAtlas>(context_, pool_, crowd_.models(), scene_.setLayout(),
                                                         scene_.set(0), impostorSettings_);
    } else if (atlas_->models().size() != pool_.modelCount()) {
        throw gpu::Error("impostors: the atlas given was baked for other models");
    }
    impostorDraw_ = std::make_unique<render::ImpostorDraw>(context_, pool_, buffers_, lists_, *atlas_, scene_.setLayout());
}

void CrowdRenderer::submit(Frame& frame, const PresentHooks* hooks) {
    VkCommandBufferSubmitInfo command{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    command.commandBuffer = frame.cmd;
    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &command;
    if (hooks && hooks->waitSemaphore) {
        wait.semaphore = hooks->waitSemaphore;
        wait.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        submit.waitSemaphoreInfoCount = 1;
        submit.pWaitSemaphoreInfos = &wait;
    }
    if (hooks && hooks->signalSemaphore) {
        signal.semaphore = hooks->signalSemaphore;
        signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signal;
    }
    VK_CHECK(vkQueueSubmit2(context_.queue, 1, &submit, frame.fence));
    frame.pending = true;
}

void CrowdRenderer::resize(VkExtent2D size) {
    finish();
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    target_.reset();
    target_ = std::make_unique<render::RenderTarget>(context_, size);
}

void CrowdRenderer::setMethod(skin::Method method) {
    finish();
    VK_CHECK(vkDeviceWaitIdle(context_.device));
    method_.reset();
    method_ = createMethod(method);
}

void CrowdRenderer::collect(Frame& frame, std::uint32_t slot) {
    if (!frame.pending) return;
    VK_CHECK(vkWaitForFences(context_.device, 1, &frame.fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(context_.device, 1, &frame.fence));
    frame.pending = false;
    frame.stats.gpu = timer_.results(slot);
    frame.stats.lods = lists_.countsOf(slot);
    stats_.push_back(frame.stats);
}

void CrowdRenderer::finish() {
    // Collect in submission order so stats_ stays in frame order.
    for (std::uint64_t i = 0; i < frames_.size(); ++i) {
        const auto slot = static_cast<std::uint32_t>((frameIndex_ + i) % frames_.size());
        collect(frames_[slot], slot);
    }
}

render::Rgba8Image CrowdRenderer::readback() {
    finish();
    return target_->readback();
}

std::vector<skin::MemoryItem> CrowdRenderer::memory() const {
    std::vector<skin::MemoryItem> items = {{"geometry pool (vertices, LOD indices, textures)", pool_.bytes()},
                                           {"character records and bone matrices", buffers_.deviceBytes()},
                                           {"clip library (GPU animation)", animationPass_.libraryBytes()},
                                           {"motion segments (GPU animation)", animationPass_.segmentBytes()},
                                           {"culling lists and draw commands", lists_.bytes()},
                                           {"render target", target_->bytes()},
                                           {"shadow map", shadowMap_.bytes()}};
    if (atlas_) items.push_back({"impostor atlas", atlas_->bytes()});
    if (impostorDraw_) items.push_back({"impostor quad indices and draws", impostorDraw_->bytes()});
    for (const skin::MemoryItem& item : method_->memory()) items.push_back(item);
    return items;
}

std::map<std::string, double> CrowdRenderer::memoryPerCharacter() const {
    const double n = std::max(crowd_.size(), 1u);
    const double state = static_cast<double>(buffers_.characters().size + animationPass_.segmentBytes() +
                                             lists_.lodState().size + lists_.impostorList().size +
                                             lists_.characterDraws().size);
    double meshSlots = static_cast<double>(lists_.visible().size + lists_.draws().size);
    for (const skin::MemoryItem& item : method_->memory()) meshSlots += static_cast<double>(item.bytes);
    const double fixed = static_cast<double>(pool_.bytes() + animationPass_.libraryBytes() + target_->bytes() +
                                             shadowMap_.bytes() + (impostorDraw_ ? impostorDraw_->bytes() : 0u));
    return {{"state", state / n},
            {"bones", static_cast<double>(buffers_.bones().size) / n},
            {"mesh slots", meshSlots / n},
            {"atlas", atlas_ ? static_cast<double>(atlas_->bytes()) / n : 0.0},
            {"fixed", fixed / n}};
}

}  // namespace frame
