// crowd-render: renders a skinned crowd headless for N frames, writes a PNG of the last frame and
// prints (and optionally writes as JSON) the timings. Without a GPU it also lists a model's clips
// (--list-clips) and writes one character's pose as OBJ (--export-pose).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/crowd_app.h"
#include "app/options.h"
#include "app/report.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "io/output_file.h"
#include "io/file_size_signal.h"
#include "io/standard_output.h"
#include "model/obj_export.h"
#include "app/crowd_renderer.h"
#include "frame/memory_plan.h"
#include "gpu/buffer.h"
#include "render/png_writer.h"

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
        throw gpu::Error("--time: '" + text + "' is not a number of seconds");
    return seconds;
}

// --list-clips and --export-pose take one model: the first of --model's list.
model::SkinnedModel loadAndNote(const app::RenderOptions& options) {
    std::vector<std::string> notes;
    model::SkinnedModel model = app::loadModel(app::parseModelList(options.scene.model).front().first,
                                               options.scene.seed, &notes, options.scene.assetRoot);
    for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
    return model;
}

int listClips(const app::RenderOptions& options) {
    const model::SkinnedModel model = loadAndNote(options);
    std::printf("%s: %zu joints, %zu vertices, %zu triangles, height %.4g\n", model.name.c_str(),
                model.skeleton.jointCount(), model.vertices.size(), model.triangleCount(), model.height());
    for (std::size_t l = 0; l < model.lods.size(); ++l)
        std::printf("  LOD %zu: %zu triangles, %u vertices\n", l, model.lods[l].indices.size() / 3,
                    model.lods[l].vertexCount);
    std::printf("  pose sphere: centre (%.4g, %.4g, %.4g), radius %.4g\n", model.poseSphere.x, model.poseSphere.y,
                model.poseSphere.z, model.poseSphere.w);
    std::printf("%zu clip(s):\n", model.clips.size());
    for (std::size_t i = 0; i < model.clips.size(); ++i)
        std::printf("  %zu: %s (%.4f s)\n", i, model.clips[i].name.c_str(), model.clips[i].duration);
    return 0;
}

int exportPose(const app::RenderOptions& options, const PoseFlags& flags) {
    const float time = flags.time.empty() ? 0.0f : parseSeconds(flags.time);
    io::checkWritable(flags.exportPose);
    const model::SkinnedModel character = loadAndNote(options);
    const std::uint32_t clip = app::clipIndex(character, options.scene.clip);
    const std::vector<skin::CpuSkinnedVertex> pose = app::poseOnCpu(character, clip, time);
    std::vector<glm::dvec3> positions, normals;
    positions.reserve(pose.size());
    normals.reserve(pose.size());
    for (const skin::CpuSkinnedVertex& v : pose) positions.push_back(v.position), normals.push_back(v.normal);
    model::writeObj(flags.exportPose, character.name, positions, normals, character.indices);
    std::printf("wrote %s: %s, clip %s at %.4f s, %zu vertices, %zu triangles\n", flags.exportPose.c_str(),
                character.name.c_str(), character.clips.empty() ? "(none)" : character.clips[clip].name.c_str(), time,
                positions.size(), character.triangleCount());
    return 0;
}

void listDevices() {
    for (const gpu::DeviceDescription& d : gpu::listDevices())
        std::printf("%u: %s (%s, Vulkan %u.%u, %s)\n", d.index, d.name.c_str(), d.type.c_str(),
                    VK_API_VERSION_MAJOR(d.apiVersion), VK_API_VERSION_MINOR(d.apiVersion), d.driver.c_str());
}

int run(const app::RenderOptions& options) {
    // Check every output before the (possibly long) run, so a bad path fails at once.
    io::checkWritable(options.out);
    if (!options.json.empty()) io::checkWritable(options.json);

    std::vector<std::string> notes;
    const app::CrowdModels models =
        app::loadModels(options.scene.model, options.scene.seed, &notes, options.scene.assetRoot);
    for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
    gpu::VulkanContext context({options.validation, options.device, {}, false});
    crowd::Crowd crowd = app::buildCrowd(models, options.scene);
    const std::uint32_t meshCapacity = options.cull.impostors ? options.meshCapacity : 0u;
    app::checkCrowdFits(context, crowd, options.method, options.size, meshCapacity);

    app::RendererOptions rendererOptions;
    rendererOptions.meshCapacity = meshCapacity;
    rendererOptions.size = options.size;
    rendererOptions.method = options.method;
    rendererOptions.cull = options.cull;
    rendererOptions.shadows = options.shadows;
    rendererOptions.animation = options.animation;
    app::CrowdRenderer renderer(context, crowd, rendererOptions);
    const render::CrowdShape shape = app::crowdShape(crowd);
    const float aspect = static_cast<float>(options.size.width) / static_cast<float>(options.size.height);
    app::RecentFrames recent(kSummarizedFrames, std::min(5u, options.frames / 4));  // warm-up left out
    for (std::uint32_t frame = 0; frame < options.frames; ++frame) {
        const double time = app::frameTime(frame, options.startSeconds);
        renderer.camera = render::cameraOnPath(options.camera, shape, aspect, time);
        renderer.renderFrame(time);
        recent.add(renderer.takeStats());
    }
    render::writePng(options.out, renderer.readback());
    recent.add(renderer.takeStats());

    app::RunSummary summary = app::summarize(recent.frames(), 0);
    summary.frames = options.frames;
    summary.scene = options.scene.scene;
    summary.culling = std::string(render::cullModeName(options.cull.mode)) + ", LOD " + (options.cull.lod ? "on" : "off") +
                      ", shadows " + (options.shadows ? "on" : "off") + app::impostorSummary(options);
    summary.animation = std::string(crowd::behaviourName(options.scene.behaviour)) + ", " +
                        render::animationPathName(options.animation) + " animation";
    summary.model = app::modelNames(models);
    summary.method = skin::methodName(options.method);
    summary.characters = crowd.size();
    summary.device = context.description.name;
    summary.driver = context.description.driver;
    summary.memory = renderer.memory();
    summary.memoryPerCharacter = renderer.memoryPerCharacter();
    if (renderer.impostorAtlas()) summary.atlasBakeMs = renderer.impostorAtlas()->bakeMs();
    app::printSummary(summary);
    // The library's promise: what memoryNeeded plans before anything exists is what was allocated.
    std::uint64_t allocated = 0;
    for (const skin::MemoryItem& item : renderer.memory())
        allocated += item.what == "render target" ? 0 : item.bytes;  // the host's, not the library's
    const std::uint64_t planned = frame::planMemory(context, crowd, rendererOptions).total();
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
        if (!pose.time.empty() && pose.exportPose.empty()) throw gpu::Error("--time needs --export-pose");
        if (pose.listClips) return listClips(options);
        if (!pose.exportPose.empty()) return exportPose(options, pose);
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
