// crowd-bench: the paper's Table 1 (fps for 1..4,096 characters, soldier and horse, per skinning
// method) plus per-pass GPU times, the cost of each method relative to the static ceiling, CPU
// times and memory, as a table, CSV and JSON.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "app/bench_table.h"
#include "app/benchmark_run.h"
#include "app/crowd_app.h"
#include "app/options.h"
#include "app/palette_bench.h"
#include "app/scene_presets.h"
#include "app/start_time.h"
#include "gpu/vulkan_context.h"
#include "gpu/vulkan_error.h"
#include "io/output_file.h"
#include "io/file_size_signal.h"
#include "io/standard_output.h"

#ifndef CROWD_COMMIT
#define CROWD_COMMIT "unknown"
#endif

namespace {

const char* kUsage = R"(crowd-bench: measures every skinning method on crowds of growing size (the paper's Table 1).

usage: crowd-bench [options]
  --scene NAME         measure a scene (paper-fig3, paper-fig4, paper-fig5, mixed, stress, default) with
                       its crowd, culling, LOD and camera path instead of Table 1; its count unless
                       --counts is given
  --lod on|off         override the levels of detail (Table 1: off, as in the paper)
  --cull gpu|cpu|off   override culling (Table 1: off, as in the paper)
  --shadows on|off     the sun's shadow map (default on; Table 1 too)
  --behaviour NAME     in-place, march or mill (default: the scene's; Table 1: in-place)
  --animation cpu|gpu  bone matrices from CPU jobs or GPU passes (default gpu)
  --impostors on|off   the impostor level for far characters (default off); with
  --impostor-threshold PX  (default 32) and --mesh-capacity N (default 65536) as in crowd-render
  --start SECONDS      scene time of the first frame (where on the scene's camera path to measure)
  --models LIST        comma-separated models, each measured alone (default soldier,horse)
  --asset-root DIR     let glTF files' buffers and images come from anywhere inside DIR (default:
                       each file's own folder and below)
  --methods LIST       comma-separated methods (default vs,vs-instanced,two-pass,two-pass-direct,compute,static)
  --counts LIST        comma-separated crowd sizes (default 1,16,64,256,1024,2048,4096)
  --frames N           measured frames per configuration (default 60)
  --warmup N           frames rendered before measuring (default 10)
  --size WxH           image size (default 1280x720)
  --pass-clock CLOCK   auto, timestamps or fence (default auto: fence on lavapipe, whose timestamps
                       do not bracket compute work, timestamps elsewhere)
  --quick              1 and 16 characters, 5 frames, 2 warm-up, 320x180: under a minute on lavapipe
  --palette            instead: bone-palette time of a milling, crossfading crowd of the first model on
                       the CPU (one thread, every thread) and on the GPU, for --counts (default
                       1024,4096,16384,65536,262144,1000000; 10 frames, 3 warm-up unless given)
  --csv FILE           every figure as CSV
  --json FILE          every figure as JSON
  --device INDEX|NAME  Vulkan device (see crowd-render --list-devices)
  --seed N             crowd layout seed (default 1)
  --validation         enable the Khronos validation layer
  --help               print this help
Frame times are wall clock between frame starts with two frames in flight; per-pass GPU times come
from the clock named in each row.
)";

app::RenderOptions tableOneScene() {
    app::RenderOptions scene = app::parseRenderOptions({"--scene", "default"});
    scene.scene.scene = "table-1";
    scene.cull.mode = render::CullMode::Off;
    scene.cull.lod = false;
    return scene;
}

struct BenchOptions {
    // Each entry is one crowd's --model list (a scene's may mix models: soldier:3,horse:1).
    std::vector<std::string> models{"soldier", "horse"};
    // The scene and its settings; Table 1 is the paper's: no culling, no LOD, the whole crowd in view.
    app::RenderOptions scene = tableOneScene();
    std::vector<std::string> methods;
    std::vector<std::uint32_t> counts{1, 16, 64, 256, 1024, 2048, 4096};
    std::uint32_t frames = 60, warmup = 10, seed = 1;
    VkExtent2D size{1280, 720};
    std::string passClock = "auto", csv, json, device, assetRoot;
    bool validation = false, help = false, palette = false;
    bool countsGiven = false, framesGiven = false;
};

// "a,b,c"; an empty item ("1,,2", a trailing comma) is an error, not skipped.
std::vector<std::string> splitList(const std::string& flag, const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (items.back().empty()) throw gpu::Error(flag + ": empty item in '" + text + "'");
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

BenchOptions parseBenchOptions(const std::vector<std::string>& args) {
    BenchOptions o;
    bool behaviourGiven = false, impostorsGiven = false, shadowsGiven = false, startGiven = false, sceneGiven = false, lodGiven = false, cullGiven = false, modelsGiven = false, countsGiven = false;
    for (skin::Method m : skin::allMethods()) o.methods.push_back(skin::methodName(m));
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& flag = args[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= args.size()) throw gpu::Error(flag + " needs a value (see --help)");
            if (args[i + 1].empty()) throw gpu::Error(flag + ": empty value");
            return args[++i];
        };
        if (flag == "--help" || flag == "-h") o.help = true;
        else if (flag == "--validation") o.validation = true;
        else if (flag == "--quick") o.counts = {1, 16}, o.frames = 5, o.warmup = 2, o.size = {320, 180};
        else if (flag == "--palette") o.palette = true;
        else if (flag == "--scene") {
            const app::ScenePreset& preset = app::findScenePreset(next());
            const render::CullSettings keep = o.scene.cull;
            const float keepStart = o.scene.startSeconds;
            const bool keepShadows = o.scene.shadows;
            const std::uint32_t keepCapacity = o.scene.meshCapacity;
            const crowd::Behaviour keepBehaviour = o.scene.scene.behaviour;
            const render::AnimationPath keepAnimation = o.scene.animation;
            o.scene = app::parseRenderOptions({"--scene", preset.name});
            o.scene.animation = keepAnimation;
            if (behaviourGiven) o.scene.scene.behaviour = keepBehaviour;
            if (impostorsGiven) {
                o.scene.cull.impostors = keep.impostors, o.scene.cull.impostorThreshold = keep.impostorThreshold;
                o.scene.meshCapacity = keepCapacity;
            }
            if (lodGiven) o.scene.cull.lod = keep.lod;
            if (cullGiven) o.scene.cull.mode = keep.mode;
            if (startGiven) o.scene.startSeconds = keepStart;
            if (shadowsGiven) o.scene.shadows = keepShadows;
            if (!modelsGiven) o.models = {preset.models};
            if (!countsGiven) o.counts = {preset.count};
            sceneGiven = true;
        } else if (flag == "--behaviour") {
            o.scene.scene.behaviour = app::parseRenderOptions({"--behaviour", next()}).scene.behaviour;
            behaviourGiven = true;
        } else if (flag == "--animation") {
            o.scene.animation = app::parseRenderOptions({"--animation", next()}).animation;
        } else if (flag == "--shadows") {
            o.scene.shadows = app::parseRenderOptions({"--shadows", next()}).shadows;
            shadowsGiven = true;
        } else if (flag == "--impostors" || flag == "--impostor-threshold" || flag == "--mesh-capacity") {
            const app::RenderOptions parsed = app::parseRenderOptions({flag, next()});
            if (flag == "--impostors") o.scene.cull.impostors = parsed.cull.impostors;
            if (flag == "--impostor-threshold") o.scene.cull.impostorThreshold = parsed.cull.impostorThreshold;
            if (flag == "--mesh-capacity") o.scene.meshCapacity = parsed.meshCapacity;
            impostorsGiven = true;
        } else if (flag == "--start") {
            o.scene.startSeconds = app::parseNumber(flag, next(), 0.0f, app::kMaxStartSeconds);
            startGiven = true;
        } else if (flag == "--lod") {
            o.scene.cull.lod = app::parseRenderOptions({"--lod", next()}).cull.lod;
            lodGiven = true;
        } else if (flag == "--cull") {
            o.scene.cull.mode = app::parseRenderOptions({"--cull", next()}).cull.mode;
            cullGiven = true;
        } else if (flag == "--models") o.models = splitList(flag, next()), modelsGiven = true;
        else if (flag == "--asset-root") o.assetRoot = next();
        else if (flag == "--methods") o.methods = splitList(flag, next());
        else if (flag == "--counts") {
            countsGiven = true;
            o.counts.clear();
            for (const std::string& c : splitList(flag, next())) o.counts.push_back(app::parseCount(flag, c, 1, app::kMaxCharacters));
        } else if (flag == "--frames") o.frames = app::parseCount(flag, next(), 1, 100000), o.framesGiven = true;
        else if (flag == "--warmup") o.warmup = app::parseCount(flag, next(), 0, 100000), o.framesGiven = true;
        else if (flag == "--size") o.size = app::parseSize(flag, next());
        else if (flag == "--pass-clock") o.passClock = next();
        else if (flag == "--csv") o.csv = next();
        else if (flag == "--json") o.json = next();
        else if (flag == "--device") o.device = next();
        else if (flag == "--seed") o.seed = app::parseCount(flag, next(), 0, UINT32_MAX);
        else throw gpu::Error("unknown option '" + flag + "' (see --help)");
    }
    (void)sceneGiven;
    o.countsGiven = countsGiven;
    for (const std::uint32_t count : o.counts) app::checkStartTime(o.scene.startSeconds, count, o.scene.scene.behaviour);
    if (o.palette && !countsGiven) o.counts = {1024, 4096, 16384, 65536, 262144, 1000000};
    if (o.palette && !o.framesGiven) o.frames = 10, o.warmup = 3;
    skin::Method method;
    for (const std::string& m : o.methods)
        if (!skin::parseMethod(m, method)) throw gpu::Error("--methods: unknown method '" + m + "'");
    if (o.passClock != "auto" && o.passClock != "timestamps" && o.passClock != "fence")
        throw gpu::Error("--pass-clock: '" + o.passClock + "' is not auto, timestamps or fence");
    return o;
}

std::string utcDate() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return text;
}

app::BenchResult measure(const gpu::VulkanContext& context, const app::CrowdModels& models,
                         const BenchOptions& options, skin::Method method, std::uint32_t count, bool fencePasses) {
    const model::SkinnedModel& model = *models.models.front();
    app::BenchResult result;
    result.model = app::modelNames(models);
    result.method = skin::methodName(method);
    result.count = count;
    result.vertices = static_cast<std::uint32_t>(model.vertices.size());
    result.triangles = static_cast<std::uint32_t>(model.triangleCount());
    app::ScenarioOptions scenario;
    scenario.scene = options.scene;
    scenario.count = count;
    scenario.method = method;
    scenario.warmup = options.warmup;
    scenario.frames = options.frames;
    scenario.size = options.size;
    scenario.seed = options.seed;
    try {
        result.frame = app::runScenario(context, models, scenario);
        result.passes = result.frame;
        if (fencePasses) {
            // A second, serialized run whose passes are timed by fences; fewer frames suffice.
            scenario.passClock = gpu::PassClock::FenceWallClock;
            scenario.warmup = std::min(options.warmup, 2u);
            scenario.frames = std::max(3u, options.frames / 4);
            result.passes = app::runScenario(context, models, scenario);
        }
        result.ok = true;
    } catch (const gpu::Error& error) {
        result.error = error.what();
    }
    return result;
}

int validationStatus(const gpu::VulkanContext& context) {
    if (context.validationMessages() == 0) return 0;
    std::fprintf(stderr, "crowd-bench: %llu validation message(s)\n",
                 static_cast<unsigned long long>(context.validationMessages()));
    return 3;
}

int runPalettes(const gpu::VulkanContext& context, const app::CrowdModels& models, const BenchOptions& options,
                const std::string& command, bool fencePasses) {
    app::PaletteBenchOptions palette;
    palette.counts = options.counts;
    palette.frames = options.frames;
    palette.warmup = options.warmup;
    palette.seed = options.seed;
    palette.clock = fencePasses ? gpu::PassClock::FenceWallClock : gpu::PassClock::TimestampQueries;
    const std::vector<app::PaletteRow> rows = app::runPaletteBench(context, models, palette);
    std::printf("crowd-bench --palette: %s, driver %s, commit %s, %s\n", context.description.name.c_str(),
                context.description.driver.c_str(), CROWD_COMMIT, utcDate().c_str());
    app::printPaletteTable(rows, app::modelNames(models));
    const app::BenchMeta meta{context.description.name, context.description.driver, CROWD_COMMIT, utcDate(), command,
                              options.frames, options.warmup, 64, 64};
    if (!options.json.empty()) app::writePaletteJson(options.json, meta, app::modelNames(models), rows);
    return validationStatus(context);
}

int run(const BenchOptions& options, const std::string& command) {
    if (!options.csv.empty()) io::checkWritable(options.csv);
    if (!options.json.empty()) io::checkWritable(options.json);
    // Every model is loaded (and a bad one reported) before the device starts and progress is printed.
    std::vector<app::CrowdModels> crowds;
    for (const std::string& modelList : options.models)
        crowds.push_back(app::loadModels(modelList, options.seed, nullptr, options.assetRoot));
    gpu::VulkanContext context({options.validation, options.device, {}, false});
    const bool fencePasses = options.passClock == "fence" ||
                             (options.passClock == "auto" && !app::timestampsBracketAllWork(context));
    std::fprintf(stderr, "crowd-bench on %s (%s); per-pass clock: %s\n", context.description.name.c_str(),
                 context.description.driver.c_str(), fencePasses ? "fence wall clock" : "timestamp queries");

    if (options.palette) return runPalettes(context, crowds.front(), options, command, fencePasses);

    std::vector<app::BenchResult> results;
    std::vector<std::string> modelNames;  // as the models name themselves (a file's model is not its path)
    const std::size_t total = options.models.size() * options.methods.size() * options.counts.size();
    for (const app::CrowdModels& models : crowds) {
        modelNames.push_back(app::modelNames(models));
        for (std::uint32_t count : options.counts)
            for (const std::string& methodName : options.methods) {
                skin::Method method;
                skin::parseMethod(methodName, method);
                std::fprintf(stderr, "[%zu/%zu] %s %s x %u\n", results.size() + 1, total, modelNames.back().c_str(),
                             methodName.c_str(), count);
                results.push_back(measure(context, models, options, method, count, fencePasses));
            }
    }

    std::printf("crowd-bench: %s, driver %s, commit %s, %s\n", context.description.name.c_str(),
                context.description.driver.c_str(), CROWD_COMMIT, utcDate().c_str());
    std::printf("%u measured frames after %u warm-up, %ux%u; frame time: wall clock between frame starts\n",
                options.frames, options.warmup, options.size.width, options.size.height);
    std::printf("scene %s: culling %s, LOD %s, shadows %s, camera %s from %.1f s\n", options.scene.scene.scene.c_str(),
                render::cullModeName(options.scene.cull.mode), options.scene.cull.lod ? "on" : "off",
                options.scene.shadows ? "on" : "off", render::cameraPathName(options.scene.camera),
                options.scene.startSeconds);
    app::printTable1(results, modelNames, options.methods, options.counts);
    app::printPassTable(results);

    app::BenchMeta meta{context.description.name, context.description.driver, CROWD_COMMIT, utcDate(), command,
                        options.frames, options.warmup, options.size.width, options.size.height};
    if (!options.csv.empty()) app::writeCsv(options.csv, meta, results);
    if (!options.json.empty()) app::writeBenchJson(options.json, meta, results);
    if (context.validationMessages() > 0) {
        std::fprintf(stderr, "crowd-bench: %llu validation message(s)\n",
                     static_cast<unsigned long long>(context.validationMessages()));
        return 3;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    io::failOnUnwrittenStandardOutput("crowd-bench");
    io::failWritesPastTheFileSizeLimit();
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        const BenchOptions options = parseBenchOptions(args);
        if (options.help) return std::printf("%s", kUsage), 0;
        std::string command = "crowd-bench";
        for (const std::string& a : args) command += " " + a;
        return run(options, command);
    } catch (const gpu::Error& error) {
        std::fprintf(stderr, "crowd-bench: %s\n", error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "crowd-bench: out of host memory\n");
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "crowd-bench: unexpected error: %s\n", error.what());
        return 2;
    }
}
