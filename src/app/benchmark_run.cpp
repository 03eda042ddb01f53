#include "app/benchmark_run.h"

#include "app/crowd_app.h"
#include "gpu/vulkan_context.h"
#include "render/crowd_renderer.h"

namespace app {

bool timestampsBracketAllWork(const gpu::VulkanContext& context) {
    return context.timestampPeriodNs() > 0.0 && context.description.driver.rfind("llvmpipe", 0) != 0;
}

RunSummary runScenario(const gpu::VulkanContext& context, const model::SkinnedModel& model,
                       const ScenarioOptions& options) {
    checkCrowdFits(context, model, options.count, options.method, options.size);
    SceneOptions scene;
    scene.count = options.count;
    scene.seed = options.seed;
    const crowd::Crowd crowd(model, buildCharacters(model, scene));
    render::RendererOptions rendererOptions;
    rendererOptions.size = options.size;
    rendererOptions.method = options.method;
    rendererOptions.passClock = options.passClock;
    render::CrowdRenderer renderer(context, crowd, rendererOptions);
    const std::uint32_t total = options.warmup + options.frames;
    for (std::uint32_t frame = 0; frame < total; ++frame) renderer.renderFrame(frameTime(frame));
    renderer.finish();

    RunSummary summary = summarize(renderer.stats(), options.warmup);
    summary.model = model.name;
    summary.method = skin::methodName(options.method);
    summary.characters = options.count;
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    summary.passClock = gpu::passClockName(options.passClock);
    return summary;
}

}  // namespace app
