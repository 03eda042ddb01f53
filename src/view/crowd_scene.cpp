#include "view/crowd_scene.h"

#include <algorithm>

#include "app/crowd_app.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "skin/storage_ranges.h"

namespace view {
namespace {

}  // namespace

CrowdScene::CrowdScene(const gpu::VulkanContext& context, const app::SceneOptions& scene, skin::Method method,
                       const render::CullSettings& cull, bool shadows, std::uint32_t meshCapacity, VkExtent2D size)
    : context_(context), scene_(scene), method_(method), cull_(cull), shadows_(shadows), meshCapacity_(meshCapacity) {
    rebuild(scene, size);
}

void CrowdScene::rebuild(app::SceneOptions scene, VkExtent2D size) {
    std::vector<std::string> notes;
    app::CrowdModels models = app::loadModels(scene.model, scene.seed, &notes, scene.assetRoot);
    std::vector<crowd::Character> characters;
    try {
        characters = app::buildCharacters(models, scene);
    } catch (const gpu::Error&) {
        // A clip named for one model (--clip idle) need not exist in the next one picked in the panel.
        if (scene.clip.empty() || scene.clip == "random" || !crowd_) throw;
        notes.push_back(models.models.front()->name + " has no clip '" + scene.clip + "'; playing its default clip");
        scene.clip.clear();
        characters = app::buildCharacters(models, scene);
    }
    crowd::BehaviourSettings behaviour;
    behaviour.kind = scene.behaviour;
    behaviour.seed = scene.seed;
    auto next = std::make_unique<crowd::Crowd>(models.pointers(), std::move(characters), behaviour);
    // The panel may have changed culling, LOD or impostors since the last build: keep what it shows.
    if (renderer_) cull_ = renderer_->cull();
    app::checkCrowdFits(context_, *next, method_, size, meshCapacityFor(cull_));

    // Release the current crowd (renderer first: it refers to the crowd, which refers to the model)
    // before allocating the next, so both never need to fit at once.
    renderer_.reset();
    crowd_ = std::move(next);
    models_ = std::move(models);
    app::RendererOptions options;
    options.size = size;
    options.method = method_;
    options.cull = cull_;
    options.meshCapacity = meshCapacityFor(cull_);
    options.shadows = shadows_;
    options.animation = animation_;
    renderer_ = std::make_unique<app::CrowdRenderer>(context_, *crowd_, options);
    scene_ = scene;
    notes_.insert(notes_.end(), notes.begin(), notes.end());
}

void CrowdScene::setMethod(skin::Method method, VkExtent2D size) {
    app::checkCrowdFits(context_, *crowd_, method, size, renderer_->drawLists().meshCapacity());
    renderer_->setMethod(method);
    method_ = method;
}

std::uint32_t CrowdScene::maxCharacters(VkExtent2D size) const {
    // Memory grows with the characters: this crowd's bytes per character (its fixed costs included,
    // so the limit errs low) against the device's memory. A rebuild still checks the real size.
    const std::uint32_t capacity = meshCapacityFor(renderer_->cull());
    const double perCharacter = static_cast<double>(app::estimateCrowdBytes(context_, *crowd_, method_, size, capacity)) /
                                static_cast<double>(std::max(crowd_->size(), 1u));
    const double memoryLimit = static_cast<double>(context_.deviceLocalBytes()) / std::max(perCharacter, 1.0);
    // Nor may a buffer bound whole as a storage buffer outgrow the device's range (lavapipe: 128 MiB).
    const double rangeLimit = static_cast<double>(
        skin::maxCharactersInStorageRange(context_.properties.limits, *crowd_, method_, capacity));
    return static_cast<std::uint32_t>(std::clamp(std::min(memoryLimit, rangeLimit), 1.0, static_cast<double>(app::kMaxCharacters)));
}

}  // namespace view
