#include "app/crowd_renderer.h"

#include <chrono>

#include "api/renderer_data.h"
#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/scene_pass.h"

namespace app {
namespace {

double nowMs() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// What the programs' device enabled (gpu::VulkanContext::createDevice), as the chain a host passes.
struct EnabledFeatures {
    VkPhysicalDeviceVulkan11Features vulkan11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};

    explicit EnabledFeatures(const gpu::VulkanContext& context) {
        vulkan12.pNext = &vulkan11;
        vulkan13.pNext = &vulkan12;
        features.pNext = &vulkan13;
        crowdgpu::enableRequiredFeatures(features, vulkan11, vulkan12, vulkan13);
        features.features.fragmentStoresAndAtomics = context.fragmentStores ? VK_TRUE : VK_FALSE;
    }
};

crowdgpu::Renderer makeRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd, const RendererOptions& options) {
    const EnabledFeatures enabled(context);
    const crowdgpu::Device device{context.instance, context.physicalDevice, context.device, context.queueFamily,
                                  &enabled.features};
    crowdgpu::RendererSettings settings;
    settings.target = {options.target.color, options.target.depth, options.target.samples};
    settings.framesInFlight = options.framesInFlight;
    settings.shadows = options.shadows;
    return crowdgpu::detail::makeRenderer(device, crowd, options, settings);
}

}  // namespace

CrowdRenderer::CrowdRenderer(const gpu::VulkanContext& context, crowd::Crowd& crowd, const RendererOptions& options)
    : context_(context),
      crowd_(crowd),
      renderer_(makeRenderer(context, crowd, options)),
      target_(std::make_unique<render::RenderTarget>(context, options.size)),
      timer_(context, options.framesInFlight, options.passClock),
      frames_(options.framesInFlight) {
    const float aspect = static_cast<float>(options.size.width) / static_cast<float>(options.size.height);
    camera = render::frameCrowd(recorder().shape().center, recorder().shape().radius, recorder().shape().characterHeight,
                                aspect);
    for (Frame& frame : frames_) {
        VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocate.commandPool = context.commandPool;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(context.device, &allocate, &frame.cmd));
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &frame.fence));
    }
    renderer_.setPassObserver([this](VkCommandBuffer cmd, const char* pass) { timer_.mark(cmd, pass); });
    runSetup();
}

CrowdRenderer::~CrowdRenderer() {
    vkDeviceWaitIdle(context_.device);
    for (Frame& frame : frames_) {
        vkDestroyFence(context_.device, frame.fence, nullptr);
        vkFreeCommandBuffers(context_.device, context_.commandPool, 1, &frame.cmd);
    }
}

frame::CrowdRecorder& CrowdRenderer::recorder() const {
    return *renderer_.data().frame;  // the library's recorder behind the public handle
}

render::FrameView CrowdRenderer::view(double time) const { return render::frameViewOf(camera, target_->extent(), time); }

void CrowdRenderer::runSetup() {
    if (!renderer_.setupPending()) return;
    const double start = nowMs();
    gpu::runOneShotNow(context_, [&](VkCommandBuffer cmd) { renderer_.recordSetup(cmd); });
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

    // 1. Motion: new segments for the characters whose plan ran out (the host's call, not the library's).
    const double planStart = nowMs();
    crowd_.advanceTo(time);
    const double recordStart = nowMs();
    frame.stats.planMs = recordStart - planStart;

    // 2-8. Upload or motion, cull, palettes, skin, shadows, draw, timestamps: one command buffer, one submit.
    VK_CHECK(vkResetCommandBuffer(frame.cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(frame.cmd, &begin));
    recordFrame(frame.cmd, slot, time, hooks);
    VK_CHECK(vkEndCommandBuffer(frame.cmd));
    submit(frame, hooks);
    frame.stats.recordMs = nowMs() - recordStart - frame.stats.animateMs;
}

void CrowdRenderer::recordFrame(VkCommandBuffer cmd, std::uint32_t slot, double time, const PresentHooks* hooks) {
    timer_.begin(cmd, slot);
    const crowdgpu::FrameView host = [&] {
        const render::FrameView v = view(time);
        crowdgpu::FrameView result;
        std::copy(&v.view[0][0], &v.view[0][0] + 16, result.view);
        std::copy(&v.projection[0][0], &v.projection[0][0] + 16, result.projection);
        result.viewport = v.viewport;
        result.time = time;
        return result;
    }();
    // On the CPU path recordCompute samples every character's clips first: that is the animation time.
    const bool cpuAnimation = recorder().method().needsAnimation() &&
                              (recorder().method().fixedLayout() || recorder().animation() == render::AnimationPath::Cpu);
    const double computeStart = nowMs();
    renderer_.recordCompute(cmd, slot, host);
    if (cpuAnimation) frames_[slot].stats.animateMs = nowMs() - computeStart;
    renderer_.recordShadows(cmd, slot);
    const float clear[4] = {render::kSkyColor.r, render::kSkyColor.g, render::kSkyColor.b, 1.0f};
    target_->beginRendering(cmd, clear);
    renderer_.recordGround(cmd, slot);
    renderer_.recordCharacters(cmd, slot);
    target_->endRendering(cmd);
    timer_.mark(cmd, "draw");
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
    VK_CHECK(vkQueueSubmit2(context_.queue, 1, &submit, frame.fence));
    frame.pending = true;
}

void CrowdRenderer::waitIdle() {
    finish();
    VK_CHECK(vkDeviceWaitIdle(context_.device));
}

void CrowdRenderer::resize(VkExtent2D size) {
    waitIdle();
    target_.reset();
    target_ = std::make_unique<render::RenderTarget>(context_, size);
}

void CrowdRenderer::setMethod(skin::Method method) {
    waitIdle();
    recorder().setMethod(method);
    runSetup();
}

void CrowdRenderer::setCull(const render::CullSettings& cull) {
    if (cull.impostors && !recorder().impostorAtlas()) waitIdle();
    recorder().setCull(cull);
    runSetup();
}

void CrowdRenderer::collect(Frame& frame, std::uint32_t slot) {
    if (!frame.pending) return;
    VK_CHECK(vkWaitForFences(context_.device, 1, &frame.fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(context_.device, 1, &frame.fence));
    frame.pending = false;
    frame.stats.gpu = timer_.results(slot);
    frame.stats.lods = recorder().countsOf(slot);
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
    std::vector<skin::MemoryItem> items = recorder().memory();
    // Where it stood in the reports before the library split: after the lists, before the shadow map.
    const auto at = std::min<std::size_t>(items.size(), 5);
    items.insert(items.begin() + static_cast<std::ptrdiff_t>(at), {"render target", target_->bytes()});
    return items;
}

std::map<std::string, double> CrowdRenderer::memoryPerCharacter() const {
    std::map<std::string, double> perCharacter = recorder().memoryPerCharacter();
    perCharacter["fixed"] += static_cast<double>(target_->bytes()) / std::max(crowd_.size(), 1u);
    return perCharacter;
}

}  // namespace app
