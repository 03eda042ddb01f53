#include "app/benchmark_run.h"

#include "app/crowd_app.h"
#include "app/crowd_renderer.h"
#include "gpu/vulkan_context.h"

namespace app {

bool timestampsBracketAllWork(const gpu::VulkanContext& context) {
    return context.timestampPeriodNs() > 0.0 && context.description.driver.rfind("llvmpipe", 0) != 0;
}

RunSummary runScenario(const gpu::VulkanContext& context, const CrowdModels& models, const ScenarioOptions& options) {
    SceneOptions scene = options.scene.scene;
    scene.count = options.count;
    scene.seed = options.seed;
    crowd::Crowd crowd = buildCrowd(models, scene);
    const std::uint32_t meshCapacity = options.scene.cull.impostors ? options.scene.meshCapacity : 0u;
    checkCrowdFits(context, crowd, options.method, options.size, meshCapacity);
    app::RendererOptions rendererOptions;
    rendererOptions.meshCapacity = meshCapacity;
    rendererOptions.atlas = options.atlas;
    rendererOptions.size = options.size;
    rendererOptions.method = options.method;
    rendererOptions.cull = options.scene.cull;
    rendererOptions.shadows = options.scene.shadows;
    rendererOptions.animation = options.scene.animation;
    rendererOptions.passClock = options.passClock;
    app::CrowdRenderer renderer(context, crowd, rendererOptions);
    const render::CrowdShape shape = crowdShape(crowd);
    const float aspect = static_cast<float>(options.size.width) / static_cast<float>(options.size.height);
    const std::uint32_t total = options.warmup + options.frames;
    for (std::uint32_t frame = 0; frame < total; ++frame) {
        const double time = frameTime(frame, options.scene.startSeconds);
        renderer.camera = render::cameraOnPath(options.scene.camera, shape, aspect, time);
        renderer.renderFrame(time);
    }
    renderer.finish();

    RunSummary summary = summarize(renderer.stats(), options.warmup);
    summary.scene = scene.scene;
    summary.culling = std::string(render::cullModeName(options.scene.cull.mode)) + ", LOD " +
                      (options.scene.cull.lod ? "on" : "off") + ", shadows " + (options.scene.shadows ? "on" : "off") +
                      impostorSummary(options.scene);
    summary.animation = std::string(crowd::behaviourName(scene.behaviour)) + ", " +
                        render::animationPathName(options.scene.animation) + " animation";
    summary.model = modelNames(models);
    summary.method = skin::methodName(options.method);
    summary.characters = options.count;
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    summary.memoryPerCharacter = renderer.memoryPerCharacter();
    if (renderer.impostorAtlas()) summary.atlasBakeMs = renderer.impostorAtlas()->bakeMs();
    summary.passClock = gpu::passClockName(options.passClock);
    return summary;
}

}  // namespace app
