#include "view/crowd_scene.h"

#include <algorithm>

#include "app/crowd_app.h"
#include "app/error.h"
#include "app/host_device.h"

namespace view {

CrowdScene::CrowdScene(const app::HostDevice& context, const app::SceneOptions& scene, crowdgpu::Method method,
                       const app::CullOptions& cull, bool shadows, std::uint32_t meshCapacity,
                       app::AntiAliasing antiAliasing, VkExtent2D size)
    : context_(context), scene_(scene), method_(method), cull_(cull), shadows_(shadows), meshCapacity_(meshCapacity),
      antiAliasing_(antiAliasing) {
    rebuild(scene, size);
}

app::RendererOptions CrowdScene::rendererOptions(crowdgpu::Method method, VkExtent2D size) const {
    app::RendererOptions options;
    static_cast<crowdgpu::RendererSettings&>(options) =
        app::rendererSettings(cull_, method, animation_, shadows_, meshCapacity_, antiAliasing_);
    options.size = size;
    return options;
}

void CrowdScene::rebuild(app::SceneOptions scene, VkExtent2D size) {
    std::vector<std::string> notes;
    app::CrowdModels models = app::loadModels(scene.model, scene.seed, &notes, scene.assetRoot, scene.props);
    const std::uint32_t frames = crowdgpu::RendererSettings{}.framesInFlight;
    auto next = [&] {
        try {
            return std::make_unique<app::World>(app::buildWorld(&context_, models, scene, frames));
        } catch (const app::Error&) {
            // A clip named for one model (--clip idle) need not exist in the next one picked in the panel.
            if (scene.clip.empty() || scene.clip == "random" || !world_) throw;
            notes.push_back(models.models.front().name() + " has no clip '" + scene.clip + "'; playing its default clip");
            scene.clip.clear();
            return std::make_unique<app::World>(app::buildWorld(&context_, models, scene, frames));
        }
    }();
    notes.insert(notes.end(), next->notes.begin(), next->notes.end());
    // The panel may have changed culling, LOD or impostors since the last build: keep what it shows.
    if (renderer_) cull_ = cullOf(renderer_->settings());
    app::checkCrowdFits(context_, next->crowd, rendererOptions(method_, size), size);
    // Release the current crowd (renderer first: it refers to the crowd) before allocating the next,
    // so both never need to fit at once.
    renderer_.reset();
    world_ = std::move(next);
    models_ = std::move(models);
    renderer_ = std::make_unique<app::CrowdRenderer>(context_, world_->crowd, rendererOptions(method_, size));
    renderer_->setDriver(world_->driver.get());
    scene_ = scene;
    notes_.insert(notes_.end(), notes.begin(), notes.end());
}

void CrowdScene::setMethod(crowdgpu::Method method, VkExtent2D size) {
    cull_ = cullOf(renderer_->settings());
    app::checkCrowdFits(context_, world_->crowd, rendererOptions(method, size), size);
    renderer_->setMethod(method);
    method_ = method;
}

void CrowdScene::setAnimation(crowdgpu::Animation path, VkExtent2D size) {
    const crowdgpu::Animation previous = animation_;
    animation_ = path;
    try {
        app::checkCrowdFits(context_, world_->crowd, rendererOptions(method_, size), size);
        renderer_->setAnimation(path);
    } catch (...) {
        animation_ = previous;
        throw;
    }
}

std::uint32_t CrowdScene::maxCharacters(VkExtent2D size) const {
    // Memory grows with the characters: this crowd's bytes per character (its fixed costs included,
    // so the limit errs low) against the device's memory. A rebuild still checks the real size.
    app::RendererOptions options = rendererOptions(method_, size);
    static_cast<crowdgpu::RendererSettings&>(options) = renderer_->settings();
    const double perCharacter = static_cast<double>(app::estimateCrowdBytes(context_, world_->crowd, options, size)) /
                                static_cast<double>(std::max(world_->crowd.size(), 1u));
    const double memoryLimit = static_cast<double>(context_.deviceLocalBytes()) / std::max(perCharacter, 1.0);
    // Nor may a buffer bound whole as a storage buffer outgrow the device's range (lavapipe: 128 MiB).
    const double rangeLimit =
        static_cast<double>(crowdgpu::checkDeviceLimits(context_.physicalDevice, world_->crowd, options).mostCharacters);
    return static_cast<std::uint32_t>(std::clamp(std::min(memoryLimit, rangeLimit), 1.0, static_cast<double>(app::kMaxCharacters)));
}

app::FittingSize CrowdScene::fittingSize(VkExtent2D window) const {
    return app::largestFittingSize(context_, world_->crowd, renderer_->settings(), window);
}

app::CullOptions cullOf(const crowdgpu::RendererSettings& settings) {
    app::CullOptions cull;
    cull.mode = settings.culling;
    cull.lod = settings.lod;
    cull.lodThresholds[0] = settings.lodThresholds[0];
    cull.lodThresholds[1] = settings.lodThresholds[1];
    cull.hysteresis = settings.lodHysteresis;
    cull.impostors = settings.impostors;
    cull.impostorThreshold = settings.impostorThreshold;
    cull.lodFade = settings.lodFade;
    cull.impostorBlend = settings.impostorBlend;
    cull.farCrowd = settings.farCrowd;
    return cull;
}

}  // namespace view
