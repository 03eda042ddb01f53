#include "app/benchmark_run.h"

#include "app/crowd_app.h"
#include "app/crowd_renderer.h"
#include "app/host_device.h"
#include "app/world.h"

namespace app {

bool timestampsBracketAllWork(const app::HostDevice& context) {
    return context.timestampPeriodNs() > 0.0 && context.description.driver.rfind("llvmpipe", 0) != 0;
}

RunSummary runScenario(const app::HostDevice& context, const CrowdModels& models, const ScenarioOptions& options) {
    SceneOptions scene = options.scene.scene;
    scene.count = options.count;
    scene.seed = options.seed;
    World world = buildWorld(&context, models, scene, crowdgpu::RendererSettings{}.framesInFlight);
    crowdgpu::Crowd& crowd = world.crowd;
    app::RendererOptions rendererOptions;
    static_cast<crowdgpu::RendererSettings&>(rendererOptions) =
        rendererSettings(options.scene.cull, options.method, options.scene.animation, options.scene.shadows,
                         options.scene.meshCapacity, options.scene.antiAliasing);
    rendererOptions.impostorsFrom = options.impostorsFrom;
    rendererOptions.size = options.size;
    rendererOptions.passClock = options.passClock;
    checkCrowdFits(context, crowd, rendererOptions, options.size);
    app::CrowdRenderer renderer(context, crowd, rendererOptions);
    renderer.setDriver(world.driver.get());
    const app::CrowdShape shape = crowdShape(crowd);
    const float aspect = static_cast<float>(options.size.width) / static_cast<float>(options.size.height);
    const std::uint32_t total = options.warmup + options.frames;
    for (std::uint32_t frame = 0; frame < total; ++frame) {
        const double time = frameTime(frame, options.scene.startSeconds);
        renderer.camera = app::cameraOnPath(options.scene.camera, shape, aspect, time);
        renderer.renderFrame(time);
    }
    renderer.finish();

    RunSummary summary = summarize(renderer.stats(), options.warmup);
    summary.scene = scene.scene;
    summary.culling = std::string(crowdgpu::cullingName(options.scene.cull.mode)) + ", LOD " +
                      (options.scene.cull.lod ? "on" : "off") + shadowSummary(options.scene) + impostorSummary(options.scene);
    summary.animation = std::string(crowdgpu::behaviourName(scene.behaviour)) + ", " +
                        crowdgpu::animationName(options.scene.animation) + " animation";
    summary.antiAliasing = antiAliasingName(options.scene.antiAliasing);
    summary.raster = crowdgpu::rasterName(options.scene.cull.raster);
    summary.model = modelNames(models);
    summary.method = crowdgpu::methodName(options.method);
    summary.characters = options.count;
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    summary.memoryPerCharacter = renderer.memoryPerCharacter();
    summary.atlasBakeMs = renderer.library().impostorBakeMs();
    summary.passClock = app::passClockName(options.passClock);
    return summary;
}

}  // namespace app
