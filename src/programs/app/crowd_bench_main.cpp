// crowd-bench: the paper's Table 1 (fps for 1..4,096 characters, soldier and horse, per skinning
// method) plus per-pass GPU times, the cost of each method relative to the static ceiling, CPU
// times and memory, as a table, CSV and JSON.
#include <algorithm>
#include <chrono>
#include <functional>
#include <utility>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "crowdgpu/crowd.hpp"
#include "app/bench_table.h"
#include "app/benchmark_run.h"
#include "app/crowd_app.h"
#include "app/options.h"
#include "app/palette_bench.h"
#include "app/scene_presets.h"
#include "app/start_time.h"
#include "app/host_memory.h"
#include "app/number_text.h"
#include "app/host_device.h"
#include "app/error.h"
#include "io/output_file.h"
#include "io/file_size_signal.h"
#include "io/standard_output.h"

#ifndef CROWD_COMMIT
#define CROWD_COMMIT "unknown"
#endif

namespace {

const char* kUsage = R"(crowd-bench: measures every skinning method on crowds of growing size (the paper's Table 1).

usage: crowd-bench [options]
  --scene NAME         measure a scene (default, paper-fig3, paper-fig4, paper-fig5, mixed, stress, march,
                       mill or cavalry) with its crowd, culling, LOD and camera path instead of Table 1; its
                       models and count unless --models and --counts are given
  --lod on|off         override the levels of detail (Table 1: off, as in the paper)
  --cull gpu|cpu|off   override culling (Table 1: off, as in the paper)
  --shadows on|off     the sun's shadow map (default on; Table 1 too)
  --shadow-lod on|off  casters' level in the shadow map from their size there (default on)
  --shadow-raster hardware|compute  the shadow map's casters by the graphics pipeline or in compute
                       (default compute)
  --shadow-cascades N  the shadow map's cascades, 1 to 4, split by distance (default 1)
  --lod-fade on|off    level changes morph and impostor changes dither instead of popping (default on)
  --impostor-blend on|off  impostors blend four atlas cells, or show the nearest (default on)
  --far-crowd average|off  impostors of 16 px or less drawn in compute add their coverage to a blended
                       layer; off: each wins whole pixels or none (default average)
  --events on|off      the GPU event buffer of the characters in view (default on; pass "events")
  --props on|off       soldiers carry their rifle (and one in eight a flag); off: the soldier without
                       props (default on; docs/props.md)
  --aa off|msaa2|msaa4|msaa8|fxaa|msaaN+fxaa  anti-aliasing, as in crowd-render (default: crowd-render's;
                       Table 1: off)
  --raster hardware|compute|auto  the impostors' rasterizer, as in crowd-render (default auto)
  --behaviour NAME     in-place, march or mill (default: the scene's; Table 1: in-place)
  --animation cpu|gpu  bone matrices from CPU jobs or GPU passes (default gpu)
  --impostors on|off   the impostor level for far characters (default off); with
  --impostor-threshold PX  (default 32) and --mesh-capacity N (default 65536) as in crowd-render
  --start SECONDS      scene time of the first frame: where on the scene's camera path and in its
                       behaviour to measure (default 0, at most 1e9)
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
  --quick              1 and 16 characters, 5 frames, 2 warm-up, 320x180 (flags given win): under a
                       minute on lavapipe
  --palette            instead: bone-palette time of a milling, crossfading crowd of the first model on
                       the CPU (one thread, every thread) and on the GPU, for --counts (default
                       1024,4096,16384,65536,262144,1000000; 10 frames, 3 warm-up unless given)
  --csv FILE           every figure as CSV
  --json FILE          every figure as JSON
  --frame-log FILE     every measured frame as a CSV row (wall clock, GPU passes, CPU, counts): where a
                       p95 comes from, frame by frame along the camera path (not with --palette)
  --device INDEX|NAME  Vulkan device (see crowd-render --list-devices)
  --seed N             crowd layout seed (default 1)
  --threads N          CPU threads that planning and CPU animation share, this one included; 0: one
                       per core (default 0)
  --validation         enable the Khronos validation layer
  --help               print this help
crowd-render's other crowd and culling flags work too (--lod-thresholds, --lod-hysteresis, --clip),
and so do its host's-world flags: --terrain, --churn, --agents, --trajectories (with --trajectory-*)
and --drive-delay (docs/host-driven.md; the CSV's cpu_ingest_ms and cpu_plan_ms time their CPU side).
Every flag takes its value as --flag=value as well.
Frame times are wall clock between frame starts with two frames in flight; per-pass GPU times come
from the clock named in each row.
)";

struct BenchOptions {
    // Each entry is one crowd's --model list (a scene's may mix models: soldier:3,horse:1).
    std::vector<std::string> models{"soldier", "horse"};
    // The scene and its settings; Table 1 is the paper's: no culling, no LOD, the whole crowd in view.
    app::RenderOptions scene;
    std::vector<std::string> methods;
    std::vector<std::uint32_t> counts{1, 16, 64, 256, 1024, 2048, 4096};
    std::uint32_t frames = 60, warmup = 10, seed = 1;
    VkExtent2D size{1280, 720};
    std::string passClock = "auto", csv, json, frameLog, device, assetRoot;
    bool validation = false, help = false, palette = false;
};

// "a,b,c"; an empty item ("1,,2", a trailing comma) is an error, not skipped.
std::vector<std::string> splitList(const std::string& flag, const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (items.back().empty()) throw app::Error(flag + ": empty item in '" + text + "'");
        if (comma == std::string::npos) return items;
        start = comma + 1;
    }
}

// Whether the command line gives `flag` (as "--flag value" or "--flag=value").
bool given(const std::vector<std::string>& args, const std::string& flag) {
    for (const std::string& a : args)
        if (a == flag || a.rfind(flag + "=", 0) == 0) return true;
    return false;
}

// crowd-render's flags that name one crowd, one method or one image: crowd-bench measures lists of
// them (--models, --counts, --methods) and writes no image.
void refuseSingleRunFlags(const std::vector<std::string>& args) {
    const std::pair<const char*, const char*> refused[] = {
        {"--model", "--models"}, {"--count", "--counts"}, {"--method", "--methods"}, {"--out", nullptr},
        {"--list-devices", nullptr}};
    for (const auto& [flag, instead] : refused)
        if (given(args, flag))
            throw app::Error("unknown option '" + std::string(flag) + "'" +
                             (instead ? std::string(" (crowd-bench measures lists: ") + instead + ")" : std::string()) +
                             " (see --help)");
}

// crowd-bench's own flags; the rest are crowd-render's, parsed by the same code (app/options.h).
app::ExtraFlagParser benchFlags(BenchOptions& o, bool& quick) {
    return [&o, &quick](const std::string& flag, const std::function<std::string()>& value) {
        if (flag == "--quick") quick = true;
        else if (flag == "--palette") o.palette = true;
        else if (flag == "--models") o.models = splitList(flag, value());
        else if (flag == "--methods") o.methods = splitList(flag, value());
        else if (flag == "--counts") {
            o.counts.clear();
            for (const std::string& c : splitList(flag, value())) o.counts.push_back(app::parseCount(flag, c, 1, app::kMaxCharacters));
        } else if (flag == "--warmup") o.warmup = app::parseCount(flag, value(), 0, 100000);
        else if (flag == "--pass-clock") o.passClock = value();
        else if (flag == "--csv") o.csv = value();
        else if (flag == "--frame-log") o.frameLog = value();
        else return false;
        return true;
    };
}

BenchOptions parseBenchOptions(const std::vector<std::string>& args) {
    refuseSingleRunFlags(args);
    BenchOptions o;
    bool quick = false;
    for (crowdgpu::Method m : app::allMethods()) o.methods.push_back(crowdgpu::methodName(m));
    o.scene = app::parseRenderOptions(args, benchFlags(o, quick));
    o.help = o.scene.help;
    o.validation = o.scene.validation;
    o.json = o.scene.json;
    o.device = o.scene.device;
    o.seed = o.scene.scene.seed;
    o.assetRoot = o.scene.scene.assetRoot;
    const bool sceneGiven = given(args, "--scene");
    // A replay's crowd is the recording's people, whatever the count: one run, not one a count.
    if (!o.scene.scene.world.trajectories.empty() && !given(args, "--counts")) o.counts = {1};
    if (sceneGiven) {
        // A scene's crowd, unless the lists are given.
        const app::ScenePreset& preset = app::findScenePreset(o.scene.scene.scene);
        if (!given(args, "--models")) o.models = {preset.models};
        if (!given(args, "--counts")) o.counts = {preset.count};
    } else {
        // Table 1, as in the paper: no culling, no LOD, no anti-aliasing, unless asked for.
        o.scene.scene.scene = "table-1";
        if (!given(args, "--cull")) o.scene.cull.mode = crowdgpu::Culling::Off;
        if (!given(args, "--lod")) o.scene.cull.lod = false;
        if (!given(args, "--aa")) o.scene.antiAliasing = {};
    }
    // Defaults of --quick and --palette; flags given anywhere on the line win over them.
    const bool countsGiven = given(args, "--counts"), framesGiven = given(args, "--frames"),
               warmupGiven = given(args, "--warmup");
    if (quick) {
        if (!countsGiven) o.counts = {1, 16};
        if (!given(args, "--size")) o.scene.size = {320, 180};
        if (!framesGiven) o.scene.frames = 5;
        if (!warmupGiven) o.warmup = 2;
    }
    // --palette times bone palettes, not frames: it has no frame to log, and writing no file while
    // exiting 0 would look like success.
    if (o.palette && !o.frameLog.empty())
        throw app::Error("--frame-log: --palette measures bone palettes, not frames; there is no frame log to write");
    if (o.palette && !countsGiven) o.counts = {1024, 4096, 16384, 65536, 262144, 1000000};
    if (o.palette && !framesGiven && !quick) o.scene.frames = 10;
    if (o.palette && !warmupGiven && !quick) o.warmup = 3;
    o.frames = framesGiven || quick || o.palette ? o.scene.frames : 60;
    o.size = o.scene.size;
    crowdgpu::Method method;
    for (const std::string& m : o.methods)
        if (!app::parseMethod(m, method)) throw app::Error("--methods: unknown method '" + m + "'");
    if (o.passClock != "auto" && o.passClock != "timestamps" && o.passClock != "fence")
        throw app::Error("--pass-clock: '" + o.passClock + "' is not auto, timestamps or fence");
    return o;
}

std::string utcDate() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return text;
}

app::BenchResult measure(const app::HostDevice& context, const app::CrowdModels& models,
                         const BenchOptions& options, crowdgpu::Method method, std::uint32_t count, bool fencePasses) {
    const crowdgpu::Model& model = models.models.front();
    app::BenchResult result;
    result.model = app::modelNames(models);
    result.method = crowdgpu::methodName(method);
    result.count = count;
    result.vertices = model.vertexCount();
    result.triangles = model.triangleCount();
    result.frame.antiAliasing = app::antiAliasingName(options.scene.antiAliasing);  // also on a skipped row
    result.frame.raster = crowdgpu::rasterName(options.scene.cull.raster);
    app::ScenarioOptions scenario;
    scenario.scene = options.scene;
    scenario.count = count;
    scenario.method = method;
    scenario.warmup = options.warmup;
    scenario.frames = options.frames;
    scenario.size = options.size;
    scenario.seed = options.seed;
    // The clock the per-pass figures come from, also for a configuration that is skipped.
    result.passes.passClock = app::passClockName(fencePasses ? app::PassClock::FenceWallClock : app::PassClock::TimestampQueries);
    try {
        result.frame = app::runScenario(context, models, scenario);
        result.passes = result.frame;
        if (fencePasses) {
            // A second, serialized run whose passes are timed by fences; fewer frames suffice.
            scenario.passClock = app::PassClock::FenceWallClock;
            scenario.warmup = std::min(options.warmup, 2u);
            scenario.frames = std::max(3u, options.frames / 4);
            result.passes = app::runScenario(context, models, scenario);
        }
        result.ok = true;
    } catch (const app::Error& error) {
        result.error = error.what();
    } catch (const crowdgpu::Error& error) {
        result.error = error.what();
    }
    return result;
}

int validationStatus(const app::HostDevice& context) {
    if (context.validationMessages() == 0) return 0;
    std::fprintf(stderr, "crowd-bench: %llu validation message(s)\n",
                 static_cast<unsigned long long>(context.validationMessages()));
    return 3;
}

// A run that measured nothing failed, even when each skip had its reason: status 1, naming the first.
int nothingMeasuredStatus(std::size_t measured, const std::string& firstSkip) {
    if (measured > 0) return 0;
    std::fprintf(stderr, "crowd-bench: every configuration was skipped (first: %s)\n", firstSkip.c_str());
    return 1;
}

// Refuses, before the device starts, counts whose crowds the host cannot hold (--palette also keeps
// one bone matrix per joint of every character for its CPU runs).
void checkHostMemory(const std::vector<app::CrowdModels>& crowds, const BenchOptions& options) {
    const std::uint32_t largest = *std::max_element(options.counts.begin(), options.counts.end());
    const std::uint64_t available = app::availableHostBytes();
    const bool cpuPalettes = options.palette || options.scene.animation == crowdgpu::Animation::Cpu ||
                             std::find(options.methods.begin(), options.methods.end(), "static") != options.methods.end();
    for (const app::CrowdModels& models : crowds) {
        const std::uint64_t needed = crowdgpu::hostBytesNeeded(models.models, largest, cpuPalettes);
        if (available > 0 && needed > available)
            throw app::Error("--counts " + std::to_string(largest) + ": a crowd of " + app::modelNames(models) +
                             " needs about " + app::formatBytes(needed) + " of host memory; " +
                             app::formatBytes(available) + " is available");
    }
}

int runPalettes(const app::HostDevice& context, const app::CrowdModels& models, const BenchOptions& options,
                const std::string& command, bool fencePasses) {
    app::PaletteBenchOptions palette;
    palette.counts = options.counts;
    palette.frames = options.frames;
    palette.warmup = options.warmup;
    palette.seed = options.seed;
    palette.clock = fencePasses ? app::PassClock::FenceWallClock : app::PassClock::TimestampQueries;
    const std::vector<app::PaletteRow> rows = app::runPaletteBench(context, models, palette);
    std::size_t measured = 0;
    std::string firstSkip;
    for (const app::PaletteRow& row : rows) {
        if (row.error.empty()) ++measured;
        else if (firstSkip.empty()) firstSkip = std::to_string(row.characters) + " characters: " + row.error;
    }
    std::printf("crowd-bench --palette: %s, driver %s, commit %s, %s\n", context.description.name.c_str(),
                context.description.driver.c_str(), CROWD_COMMIT, utcDate().c_str());
    app::printPaletteTable(rows, app::modelNames(models));
    const app::BenchMeta meta{context.description.name, context.description.driver, CROWD_COMMIT, utcDate(), command,
                              options.frames, options.warmup, 64, 64};
    if (!options.csv.empty()) app::writePaletteCsv(options.csv, meta, app::modelNames(models), rows);
    if (!options.json.empty()) app::writePaletteJson(options.json, meta, app::modelNames(models), rows);
    if (const int status = validationStatus(context)) return status;
    return nothingMeasuredStatus(measured, firstSkip);
}

int run(const BenchOptions& options, const std::string& command) {
    if (!options.csv.empty()) io::checkWritable(options.csv);
    if (!options.json.empty()) io::checkWritable(options.json);
    if (!options.frameLog.empty()) io::checkWritable(options.frameLog);
    // Every model is loaded (and a bad one reported) before the device starts and progress is printed.
    std::vector<app::CrowdModels> crowds;
    for (const std::string& modelList : options.models)
        crowds.push_back(app::loadModels(modelList, options.seed, nullptr, options.assetRoot, options.scene.scene.props));
    checkHostMemory(crowds, options);
    app::HostDevice context({options.validation, options.device, {}, false});
    // Once, before any row: a sample count the device lacks would otherwise skip every configuration.
    if (!options.palette) app::checkAntiAliasing(context, options.scene.antiAliasing.samples);
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
                crowdgpu::Method method;
                app::parseMethod(methodName, method);
                std::fprintf(stderr, "[%zu/%zu] %s %s x %u\n", results.size() + 1, total, modelNames.back().c_str(),
                             methodName.c_str(), count);
                results.push_back(measure(context, models, options, method, count, fencePasses));
            }
    }

    std::printf("crowd-bench: %s, driver %s, commit %s, %s\n", context.description.name.c_str(),
                context.description.driver.c_str(), CROWD_COMMIT, utcDate().c_str());
    std::printf("%u measured frames after %u warm-up, %ux%u; frame time: wall clock between frame starts\n",
                options.frames, options.warmup, options.size.width, options.size.height);
    std::printf("scene %s: culling %s, LOD %s, fades %s, impostor blend %s, far crowd %s, shadows %s, "
                "anti-aliasing %s, camera %s from %.1f s\n",
                options.scene.scene.scene.c_str(), crowdgpu::cullingName(options.scene.cull.mode),
                options.scene.cull.lod ? "on" : "off", options.scene.cull.lodFade ? "on" : "off",
                options.scene.cull.impostorBlend ? "on" : "off", options.scene.cull.farCrowd ? "average" : "off",
                options.scene.shadows ? "on" : "off",
                app::antiAliasingName(options.scene.antiAliasing).c_str(), app::cameraPathName(options.scene.camera),
                options.scene.startSeconds);
    app::printTable1(results, modelNames, options.methods, options.counts);
    app::printPassTable(results);

    app::BenchMeta meta{context.description.name, context.description.driver, CROWD_COMMIT, utcDate(), command,
                        options.frames, options.warmup, options.size.width, options.size.height};
    if (!options.csv.empty()) app::writeCsv(options.csv, meta, results);
    if (!options.json.empty()) app::writeBenchJson(options.json, meta, results);
    if (!options.frameLog.empty()) app::writeFrameLog(options.frameLog, results);
    if (const int status = validationStatus(context)) return status;
    const auto skipped = std::find_if(results.begin(), results.end(), [](const app::BenchResult& r) { return !r.ok; });
    const std::size_t measured = static_cast<std::size_t>(
        std::count_if(results.begin(), results.end(), [](const app::BenchResult& r) { return r.ok; }));
    return nothingMeasuredStatus(measured, skipped == results.end() ? "" : skipped->model + " " + skipped->method +
                                                                                " x " + std::to_string(skipped->count) +
                                                                                ": " + skipped->error);
}

}  // namespace

int main(int argc, char** argv) {
    io::failOnUnwrittenStandardOutput("crowd-bench");
    io::failWritesPastTheFileSizeLimit();
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        const BenchOptions options = parseBenchOptions(args);
        if (options.help) return std::printf("%s", kUsage), 0;
        crowdgpu::setWorkerThreads(options.scene.threads);
        std::string command = "crowd-bench";
        for (const std::string& a : args) command += " " + a;
        return run(options, command);
    } catch (const app::Error& error) {
        std::fprintf(stderr, "crowd-bench: %s\n", error.what());
        return 1;
    } catch (const crowdgpu::Error& error) {
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
