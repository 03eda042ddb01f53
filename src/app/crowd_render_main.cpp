// crowd-render: renders a skinned crowd headless for N frames, writes a PNG of the last frame and
// prints (and optionally writes as JSON) the timings.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/crowd_app.h"
#include "app/options.h"
#include "app/report.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "render/crowd_renderer.h"
#include "render/png_writer.h"

namespace {

void listDevices() {
    for (const gpu::DeviceDescription& d : gpu::listDevices())
        std::printf("%u: %s (%s, Vulkan %u.%u, %s)\n", d.index, d.name.c_str(), d.type.c_str(),
                    VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion), d.driver.c_str());
}

int run(const app::RenderOptions& options) {
    // Check every output before the (possibly long) run, so a bad path fails at once.
    render::checkWritable(options.out);
    if (!options.json.empty()) render::checkWritable(options.json);

    const model::SkinnedModel model = app::loadModel(options.scene.model, options.scene.seed);
    gpu::VulkanContext context({options.validation, options.device, {}, false});
    app::checkCrowdFits(context, model, options.scene.count, options.method, options.size);
    const crowd::Crowd crowd(model, app::buildCharacters(model, options.scene));

    render::RendererOptions rendererOptions;
    rendererOptions.size = options.size;
    rendererOptions.method = options.method;
    render::CrowdRenderer renderer(context, crowd, rendererOptions);
    for (std::uint32_t frame = 0; frame < options.frames; ++frame) renderer.renderFrame(app::frameTime(frame));
    render::writePng(options.out, renderer.readback());

    app::RunSummary summary = app::summarize(renderer.stats(), std::min(5u, options.frames / 4));
    summary.model = model.name;
    summary.method = skin::methodName(options.method);
    summary.characters = crowd.size();
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    app::printSummary(summary);
    std::printf("  wrote %s\n", options.out.c_str());
    if (!options.json.empty()) app::writeJson(options.json, summary);
    if (context.validationMessages() > 0) {
        std::fprintf(stderr, "crowd-render: %llu validation message(s)\n",
                     static_cast<unsigned long long>(context.validationMessages()));
        return 3;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const app::RenderOptions options = app::parseRenderOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (options.help) return std::printf("%s", app::renderUsage()), 0;
        if (options.listDevices) return listDevices(), 0;
        return run(options);
    } catch (const gpu::Error& error) {
        std::fprintf(stderr, "crowd-render: %s\n", error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "crowd-render: out of host memory (try a smaller --count or --size)\n");
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "crowd-render: unexpected error: %s\n", error.what());
        return 2;
    }
}
