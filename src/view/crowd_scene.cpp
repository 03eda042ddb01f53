#include "view/crowd_scene.h"

#include "app/crowd_app.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"

namespace view {
namespace {

bool fits(const gpu::VulkanContext& context, const model::SkinnedModel& model, std::uint32_t count,
          skin::Method method, VkExtent2D size) {
    try {
        app::checkCrowdFits(context, model, count, method, size);
        return true;
    } catch (const gpu::Error&) {
        return false;
    }
}

}  // namespace

CrowdScene::CrowdScene(const gpu::VulkanContext& context, const app::SceneOptions& scene, skin::Method method,
                       VkExtent2D size)
    : context_(context), scene_(scene), method_(method) {
    rebuild(scene, size);
}

void CrowdScene::rebuild(app::SceneOptions scene, VkExtent2D size) {
    std::vector<std::string> notes;
    auto model =
        std::make_unique<model::SkinnedModel>(app::loadModel(scene.model, scene.seed, &notes, scene.assetRoot));
    std::vector<crowd::Character> characters;
    try {
        characters = app::buildCharacters(*model, scene);
    } catch (const gpu::Error&) {
        // A clip named for one model (--clip idle) need not exist in the next one picked in the panel.
        if (scene.clip.empty() || scene.clip == "random" || !model_) throw;
        notes.push_back(model->name + " has no clip '" + scene.clip + "'; playing its default clip");
        scene.clip.clear();
        characters = app::buildCharacters(*model, scene);
    }
    app::checkCrowdFits(context_, *model, scene.count, method_, size);

    // Release the current crowd (renderer first: it refers to the crowd, which refers to the model)
    // before allocating the next, so both never need to fit at once.
    renderer_.reset();
    crowd_.reset();
    model_ = std::move(model);
    crowd_ = std::make_unique<crowd::Crowd>(*model_, std::move(characters));
    render::RendererOptions options;
    options.size = size;
    options.method = method_;
    renderer_ = std::make_unique<render::CrowdRenderer>(context_, *crowd_, options);
    scene_ = scene;
    notes_.insert(notes_.end(), notes.begin(), notes.end());
}

void CrowdScene::setMethod(skin::Method method, VkExtent2D size) {
    app::checkCrowdFits(context_, *model_, scene_.count, method, size);
    renderer_->setMethod(method);
    method_ = method;
}

std::uint32_t CrowdScene::maxCharacters(VkExtent2D size) const {
    // checkCrowdFits is arithmetic only, so a binary search over it costs microseconds.
    std::uint32_t lo = 1, hi = app::kMaxCharacters;
    if (fits(context_, *model_, hi, method_, size)) return hi;
    while (hi - lo > 1) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        (fits(context_, *model_, mid, method_, size) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace view
