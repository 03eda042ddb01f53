#include "app/crowd_renderer.h"

#include <algorithm>
#include <chrono>

#include "app/error.h"
#include "app/host_device.h"

namespace app {
namespace {

double nowMs() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

CrowdRenderer::CrowdRenderer(const HostDevice& device, crowdgpu::Crowd& crowd, const RendererOptions& options)
    : CrowdRenderer(device, crowd, crowdgpu::Renderer(device.libraryDevice(), crowd, options), options.size,
                    options.passClock) {}

CrowdRenderer::CrowdRenderer(const HostDevice& device, crowdgpu::Crowd& crowd, crowdgpu::Renderer renderer,
                             VkExtent2D size, PassClock passClock)
    : device_(device),
      crowd_(crowd),
      renderer_(std::move(renderer)),
      target_(std::make_unique<RenderTarget>(device, size, renderer_.settings().target, renderer_.settings().edgeFilter)),
      timer_(device, renderer_.settings().framesInFlight, passClock),
      frames_(renderer_.settings().framesInFlight) {
    camera = frameCrowd(crowdShape(crowd), static_cast<float>(size.width) / static_cast<float>(size.height));
    for (Frame& frame : frames_) {
        VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocate.commandPool = device.commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        CHECK_VK(vkAllocateCommandBuffers(device.device, &allocate, &frame.cmd));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        CHECK_VK(vkCreateFence(device.device, &fenceInfo, nullptr, &frame.fence));
    }
    renderer_.setPassObserver([this](VkCommandBuffer cmd, const char* pass) { timer_.mark(cmd, pass); });
    runSetup();
}

CrowdRenderer::~CrowdRenderer() {
    vkDeviceWaitIdle(device_.device);
    for (Frame& frame : frames_) {
        vkDestroyFence(device_.device, frame.fence, nullptr);
        vkFreeCommandBuffers(device_.device, device_.commandPool, 1, &frame.cmd);
    }
}

void CrowdRenderer::runSetup() {
    if (!renderer_.setupPending()) return;
    const double start = nowMs();
    device_.submitAndWait([&](VkCommandBuffer cmd) { renderer_.recordSetup(cmd); });
    renderer_.setupCompleted();
    setupMs_ += nowMs() - start;
}

void CrowdRenderer::renderFrame(double time, const PresentHooks* hooks) {
    const auto slot = static_cast<std::uint32_t>(frameIndex_++ % frames_.size());
    Frame& frame = frames_[slot];
    const double start = nowMs();
    collect(frame, slot);  // the slot's previous frame must be done before its buffers are reused
    frame.stats = {};
    frame.stats.intervalMs = lastFrameStart_ < 0.0 ? 0.0 : start - lastFrameStart_;
    lastFrameStart_ = start;
    frame.stats.sceneSeconds = time;

    // 1. The world: who enters and leaves, and the samples of driven characters (the host's), then motion:
    // new segments for the characters whose plan ran out (the host's call, not the library's).
    const double driveStart = nowMs();
    if (driver_) frame.stats.ingestMs = driver_->update(crowd_, time);
    const double planStart = nowMs();
    frame.stats.driveMs = planStart - driveStart;
    crowd_.advanceTo(time);
    const double recordStart = nowMs();
    frame.stats.planMs = recordStart - planStart;

    // 2-8. Upload or motion, cull, palettes, skin, shadows, draw, timestamps: one command buffer, one submit.
    CHECK_VK(vkResetCommandBuffer(frame.cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    CHECK_VK(vkBeginCommandBuffer(frame.cmd, &begin));
    recordFrame(frame.cmd, slot, time, hooks);
    CHECK_VK(vkEndCommandBuffer(frame.cmd));
    submit(frame, hooks);
    frame.stats.recordMs = nowMs() - recordStart - frame.stats.animateMs;
}

void CrowdRenderer::recordFrame(VkCommandBuffer cmd, std::uint32_t slot, double time, const PresentHooks* hooks) {
    timer_.begin(cmd, slot);
    // On the CPU path recordCompute samples every character's clips first: that is the animation time.
    const double computeStart = nowMs();
    // The host's own pass that writes device samples, when the world has one.
    const crowdgpu::DeviceSamples* samples = driver_ ? driver_->recordBeforeCompute(cmd, slot, time) : nullptr;
    if (samples)
        renderer_.recordCompute(cmd, slot, frameView(camera, target_->extent(), time), crowd_, *samples);
    else
        renderer_.recordCompute(cmd, slot, frameView(camera, target_->extent(), time), crowd_);
    if (renderer_.animatesOnCpu()) frames_[slot].stats.animateMs = nowMs() - computeStart;
    renderer_.recordShadows(cmd, slot);
    const float* horizon = crowdgpu::kHorizonColor;
    const float clear[4] = {horizon[0], horizon[1], horizon[2], 1.0f};
    // With the sky on, recordCharacters writes every pixel: no colour clear (docs/gpu-driven-frame.md).
    target_->beginRendering(cmd, clear, renderer_.settings().sky ? ColourLoad::DrawnWhole : ColourLoad::Clear);
    renderer_.recordCharacters(cmd, slot);  // with the ground behind them (RendererSettings::ground)
    target_->endRendering(cmd);
    timer_.mark(cmd, "draw");
    if (target_->edgeFiltered()) {  // --aa fxaa: the picture anti-aliased in compute (its pass: "edge filter")
        renderer_.recordEdgeFilter(cmd, slot, target_->filterSource(), target_->filterDestination(), target_->extent());
        target_->endFiltering(cmd);
    }
    if (hooks && hooks->recordAfterScene) hooks->recordAfterScene(cmd, target_->colorImage(), target_->extent());
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
    CHECK_VK(vkQueueSubmit2(device_.queue, 1, &submit, frame.fence));
    frame.pending = true;
}

void CrowdRenderer::waitIdle() {
    finish();
    CHECK_VK(vkDeviceWaitIdle(device_.device));
}

void CrowdRenderer::resize(VkExtent2D size) {
    waitIdle();
    target_.reset();
    target_ = std::make_unique<RenderTarget>(device_, size, renderer_.settings().target,
                                             renderer_.settings().edgeFilter);
}

void CrowdRenderer::setMethod(crowdgpu::Method method) {
    waitIdle();
    renderer_.setMethod(method);
    runSetup();
}

void CrowdRenderer::setCulling(crowdgpu::Culling culling, bool lod, bool impostors) {
    // The first switch to impostors makes the atlas, whose setup is recorded with the GPU idle.
    if (impostors && !renderer_.settings().impostors) waitIdle();
    renderer_.setCulling(culling, lod);
    renderer_.setImpostors(impostors);
    runSetup();
}

void CrowdRenderer::collect(Frame& frame, std::uint32_t slot) {
    if (!frame.pending) return;
    CHECK_VK(vkWaitForFences(device_.device, 1, &frame.fence, VK_TRUE, UINT64_MAX));
    CHECK_VK(vkResetFences(device_.device, 1, &frame.fence));
    frame.pending = false;
    frame.stats.gpu = timer_.results(slot);
    frame.stats.lods = renderer_.counts(slot);
    stats_.push_back(frame.stats);
}

void CrowdRenderer::finish() {
    // Collect in submission order so stats_ stays in frame order.
    for (std::uint64_t i = 0; i < frames_.size(); ++i) {
        const auto slot = static_cast<std::uint32_t>((frameIndex_ + i) % frames_.size());
        collect(frames_[slot], slot);
    }
}

Rgba8Image CrowdRenderer::readback() {
    finish();
    return target_->readback();
}

std::vector<crowdgpu::MemoryItem> CrowdRenderer::memory() const {
    std::vector<crowdgpu::MemoryItem> items = renderer_.memory();
    // Where it stood in the reports before the library split: after the lists, before the shadow map.
    const auto at = std::min<std::size_t>(items.size(), 5);
    items.insert(items.begin() + static_cast<std::ptrdiff_t>(at), {"render target", target_->bytes()});
    return items;
}

std::map<std::string, double> CrowdRenderer::memoryPerCharacter() const {
    std::map<std::string, double> perCharacter = renderer_.memoryPerCharacter();
    perCharacter["fixed"] += static_cast<double>(target_->bytes()) / std::max(crowd_.size(), 1u);
    return perCharacter;
}

}  // namespace app
