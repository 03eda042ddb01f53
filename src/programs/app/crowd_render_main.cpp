// crowd-render: renders a skinned crowd headless for N frames, writes a PNG of the last frame and
// prints (and optionally writes as JSON) the timings. Without a GPU it also lists a model's clips
// (--list-clips) and writes one character's pose as OBJ (--export-pose).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "crowdgpu/crowd.hpp"
#include "app/crowd_app.h"
#include "app/options.h"
#include "app/report.h"
#include "app/host_device.h"
#include "app/error.h"
#include "io/output_file.h"
#include "io/file_size_signal.h"
#include "io/standard_output.h"
#include "app/obj_export.h"
#include "app/crowd_renderer.h"
#include "app/png_writer.h"
#include "app/replay_driver.h"
#include "app/state_export.h"
#include "app/world.h"

namespace {

// The summary's medians are of at most this many frames, the last ones (about 2 MiB of statistics).
constexpr std::size_t kSummarizedFrames = 10000;

// crowd-render's own flags, beyond those every program shares.
struct PoseFlags {
    bool listClips = false;
    std::string exportPose;  // OBJ path
    std::string time;        // seconds into the clip, as typed
};

float parseSeconds(const std::string& text) {
    float seconds = 0.0f;
    const auto [ptr, error] = std::from_chars(text.data(), text.data() + text.size(), seconds);
    if (text.empty() || error != std::errc() || ptr != text.data() + text.size() || !std::isfinite(seconds))
        throw app::Error("--time: '" + text + "' is not a number of seconds");
    return seconds;
}

// --list-clips and --export-pose take one model: the first of --model's list.
crowdgpu::Model loadAndNote(const app::RenderOptions& options) {
    std::vector<std::string> notes;
    crowdgpu::Model model = app::loadModel(app::parseModelList(options.scene.model).front().first,
                                               options.scene.seed, &notes, options.scene.assetRoot, options.scene.props);
    for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
    return model;
}

int listClips(const app::RenderOptions& options) {
    const crowdgpu::Model model = loadAndNote(options);
    std::printf("%s: %u joints, %u vertices, %u triangles, height %.4g\n", model.name().c_str(), model.jointCount(),
                model.vertexCount(), model.triangleCount(), model.height());
    for (std::uint32_t l = 0; l < model.lodCount(); ++l)
        std::printf("  LOD %u: %u triangles, %u vertices\n", l, model.lodTriangles(l), model.lodVertices(l));
    float center[3], radius = 0.0f;
    model.poseSphere(center, radius);
    std::printf("  pose sphere: centre (%.4g, %.4g, %.4g), radius %.4g\n", center[0], center[1], center[2], radius);
    std::printf("%u clip(s):\n", model.clipCount());
    for (std::uint32_t i = 0; i < model.clipCount(); ++i)
        std::printf("  %u: %s (%.4f s)\n", i, model.clipName(i).c_str(), model.clipDuration(i));
    return 0;
}

int exportPose(const app::RenderOptions& options, const PoseFlags& flags) {
    const float time = flags.time.empty() ? 0.0f : parseSeconds(flags.time);
    io::checkWritable(flags.exportPose);
    const crowdgpu::Model character = loadAndNote(options);
    const std::uint32_t clip = app::clipIndex(character, options.scene.clip);
    std::vector<glm::dvec3> positions, normals;
    for (const crowdgpu::Model::PosedVertex& v : character.pose(clip, time)) {
        positions.emplace_back(v.position[0], v.position[1], v.position[2]);
        normals.emplace_back(v.normal[0], v.normal[1], v.normal[2]);
    }
    app::writeObj(flags.exportPose, character.name(), positions, normals, character.indices());
    std::printf("wrote %s: %s, clip %s at %.4f s, %zu vertices, %u triangles\n", flags.exportPose.c_str(),
                character.name().c_str(), character.clipCount() == 0 ? "(none)" : character.clipName(clip).c_str(), time,
                positions.size(), character.triangleCount());
    return 0;
}

void listDevices() {
    for (const app::DeviceDescription& d : app::listDevices())
        std::printf("%u: %s (%s, Vulkan %u.%u, %s)\n", d.index, d.name.c_str(), d.type.c_str(),
                    VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion), d.driver.c_str());
}

int run(const app::RenderOptions& options) {
    // Check every output before the (possibly long) run, so a bad path fails at once.
    io::checkWritable(options.out);
    if (!options.json.empty()) io::checkWritable(options.json);

    std::vector<std::string> notes;
    const app::CrowdModels models =
        app::loadModels(options.scene.model, options.scene.seed, &notes, options.scene.assetRoot, options.scene.props);
    for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
    app::HostDevice context({options.validation, options.device, {}, false});
    app::World world = app::buildWorld(&context, models, options.scene, crowdgpu::RendererSettings{}.framesInFlight);
    for (const std::string& note : world.notes) std::printf("note: %s\n", note.c_str());
    crowdgpu::Crowd& crowd = world.crowd;
    std::optional<app::StateExport> states;
    if (!options.scene.world.exportStates.empty())
        states.emplace(options.scene.world.exportStates, crowd, options.scene.world.exportJoints);
    app::RendererOptions rendererOptions;
    static_cast<crowdgpu::RendererSettings&>(rendererOptions) =
        app::rendererSettings(options.cull, options.method, options.animation, options.shadows, options.meshCapacity,
                              options.antiAliasing);
    rendererOptions.size = options.size;
    app::checkCrowdFits(context, crowd, rendererOptions, options.size);
    app::CrowdRenderer renderer(context, crowd, rendererOptions);
    renderer.setDriver(world.driver.get());
    const app::CrowdShape shape = app::crowdShape(crowd);
    const auto* replay = dynamic_cast<const app::ReplayDriver*>(world.driver.get());
    const float aspect = static_cast<float>(options.size.width) / static_cast<float>(options.size.height);
    app::RecentFrames recent(kSummarizedFrames, std::min(5u, options.frames / 4));  // warm-up left out
    for (std::uint32_t frame = 0; frame < options.frames; ++frame) {
        const double time = app::frameTime(frame, options.startSeconds);
        renderer.camera = app::cameraOnPath(options.camera, shape, aspect, time);
        renderer.renderFrame(time);
        if (states) states->frame(crowd, time, replay);
        recent.add(renderer.takeStats());
    }
    if (states) {
        states->write();
        std::printf("  wrote %s (%zu rows)\n", options.scene.world.exportStates.c_str(), states->rows());
    }
    app::writePng(options.out, renderer.readback());
    recent.add(renderer.takeStats());

    app::RunSummary summary = app::summarize(recent.frames(), 0);
    summary.frames = options.frames;
    summary.scene = options.scene.scene;
    summary.culling = std::string(crowdgpu::cullingName(options.cull.mode)) + ", LOD " + (options.cull.lod ? "on" : "off") +
                      app::shadowSummary(options) + app::impostorSummary(options);
    summary.animation = std::string(crowdgpu::behaviourName(options.scene.behaviour)) + ", " +
                        crowdgpu::animationName(options.animation) + " animation";
    summary.antiAliasing = app::antiAliasingName(options.antiAliasing);
    summary.raster = crowdgpu::rasterName(options.cull.raster);
    summary.model = app::modelNames(models);
    summary.method = crowdgpu::methodName(options.method);
    summary.characters = crowd.liveCount();
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    summary.memoryPerCharacter = renderer.memoryPerCharacter();
    summary.atlasBakeMs = renderer.library().impostorBakeMs();
    app::printSummary(summary);
    // The library's promise: what memoryNeeded plans before anything exists is what was allocated.
    std::uint64_t allocated = 0;
    for (const crowdgpu::MemoryItem& item : renderer.memory())
        allocated += item.what == "render target" ? 0 : item.bytes;  // the host's, not the library's
    const std::uint64_t planned = crowdgpu::memoryNeeded(context.physicalDevice, crowd, rendererOptions);
    std::printf("  library memory: %llu bytes planned, %llu allocated (%+.2f %%)\n",
                static_cast<unsigned long long>(planned), static_cast<unsigned long long>(allocated),
                100.0 * (static_cast<double>(planned) / static_cast<double>(std::max<std::uint64_t>(allocated, 1)) - 1.0));
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
    io::failOnUnwrittenStandardOutput("crowd-render");
    io::failWritesPastTheFileSizeLimit();
    try {
        PoseFlags pose;
        const app::RenderOptions options = app::parseRenderOptions(
            std::vector<std::string>(argv + 1, argv + argc),
            [&](const std::string& flag, const std::function<std::string()>& value) {
                if (flag == "--list-clips") pose.listClips = true;
                else if (flag == "--export-pose") pose.exportPose = value();
                else if (flag == "--time") pose.time = value();
                else return false;
                return true;
            });
        if (options.help) return std::printf("%s", app::renderUsage()), 0;
        if (options.listDevices) return listDevices(), 0;
        crowdgpu::setWorkerThreads(options.threads);
        if (!pose.time.empty() && pose.exportPose.empty()) throw app::Error("--time needs --export-pose");
        if (pose.listClips) return listClips(options);
        if (!pose.exportPose.empty()) return exportPose(options, pose);
        return run(options);
    } catch (const app::Error& error) {
        std::fprintf(stderr, "crowd-render: %s\n", error.what());
        return 1;
    } catch (const crowdgpu::Error& error) {
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
