#include "app/palette_bench.h"

#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/report.h"
#include "app/crowd_renderer.h"
#include "app/error.h"
#include "io/output_file.h"

namespace app {
namespace {

crowdgpu::Crowd millingCrowd(const CrowdModels& models, std::uint32_t count, std::uint32_t seed) {
    SceneOptions scene;
    scene.count = count;
    scene.seed = seed;
    scene.behaviour = crowdgpu::Behaviour::Mill;
    return buildCrowd(models, scene);
}

// Median wall-clock milliseconds of `runs` CPU animations of the whole crowd (Crowd::computePalettes).
double cpuPaletteMs(const crowdgpu::Crowd& crowd, double time, bool allCores, std::uint32_t runs) {
    std::vector<float> rows;
    crowd.computePalettes(time, rows, allCores);  // warm: key cursors, per-thread scratch, the rows
    std::vector<double> ms;
    for (std::uint32_t r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        crowd.computePalettes(time + 0.01 * static_cast<double>(r + 1), rows, allCores);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return median(ms);
}

// The GPU passes with every character in view at LOD 0 (no culling, no LOD), so each gets a palette.
// vs-instanced skins while drawing and needs no skinned buffer; a 64x64 image keeps the draw small.
constexpr VkExtent2D kGpuImage{64, 64};
app::RendererOptions gpuRunOptions(PassClock clock) {
    app::RendererOptions renderer;
    renderer.size = kGpuImage;
    renderer.method = crowdgpu::Method::VertexShaderInstanced;
    renderer.culling = crowdgpu::Culling::Off;
    renderer.lod = false;
    renderer.shadows = false;
    renderer.animation = crowdgpu::Animation::Gpu;
    renderer.passClock = clock;
    return renderer;
}

void gpuPaletteMs(const app::HostDevice& context, crowdgpu::Crowd& crowd, const PaletteBenchOptions& options,
                  PaletteRow& row) {
    app::CrowdRenderer frames(context, crowd, gpuRunOptions(options.clock));
    const std::uint32_t total = options.warmup + options.frames;
    for (std::uint32_t f = 0; f < total; ++f) frames.renderFrame(options.time + static_cast<double>(f) / 60.0);
    frames.finish();
    const RunSummary summary = summarize(frames.stats(), options.warmup);
    row.gpuPaletteMs = summary.medianGpuMs.count("palette") ? summary.medianGpuMs.at("palette") : 0.0;
    row.gpuMotionMs = summary.medianGpuMs.count("motion") ? summary.medianGpuMs.at("motion") : 0.0;
    row.gpuClock = app::passClockName(options.clock);  // the clock that ran (summarize() cannot know it)
}

double jointsPerSecond(std::uint64_t joints, double ms) { return ms > 0.0 ? static_cast<double>(joints) / (ms * 1e-3) : 0.0; }

}  // namespace

// Why a count cannot be measured on this device (its GPU passes' crowd does not fit), or "".
std::string whyNotMeasurable(const app::HostDevice& context, const CrowdModels& models, std::uint32_t count,
                             std::uint32_t seed) {
    try {
        checkCrowdFits(context, millingCrowd(models, count, seed), gpuRunOptions(PassClock::TimestampQueries), kGpuImage);
    } catch (const app::Error& error) {
        return error.what();
    } catch (const crowdgpu::Error& error) {
        return error.what();
    }
    return "";
}

std::vector<PaletteRow> runPaletteBench(const app::HostDevice& context, const CrowdModels& models,
                                        const PaletteBenchOptions& options) {
    // Every count is decided before any is measured: a row that cannot run costs no measuring time.
    std::vector<PaletteRow> rows;
    for (std::uint32_t count : options.counts) {
        PaletteRow row;
        row.characters = count;
        row.threads = crowdgpu::workerThreads();  // what computePalettes(allCores) shares (--threads)
        row.gpuClock = app::passClockName(options.clock);
        row.error = whyNotMeasurable(context, models, count, options.seed);
        if (!row.error.empty()) std::fprintf(stderr, "palettes: %u characters: skipped: %s\n", count, row.error.c_str());
        rows.push_back(row);
    }
    for (PaletteRow& row : rows) {
        if (!row.error.empty()) continue;
        const std::uint32_t count = row.characters;
        std::fprintf(stderr, "palettes: %u characters\n", count);
        try {
            crowdgpu::Crowd crowd = millingCrowd(models, count, options.seed);
            crowd.advanceTo(options.time);
            row.joints = crowd.paletteJoints();
            row.cpuOneThreadMs = cpuPaletteMs(crowd, options.time, false, options.cpuRuns);
            row.cpuAllThreadsMs = cpuPaletteMs(crowd, options.time, true, options.cpuRuns);
            gpuPaletteMs(context, crowd, options, row);
        } catch (const app::Error& error) {
            row.error = error.what();
        } catch (const crowdgpu::Error& error) {
            row.error = error.what();
        }
    }
    return rows;
}

void printPaletteTable(const std::vector<PaletteRow>& rows, const std::string& model) {
    std::printf("\nBone palettes of a milling, crossfading crowd (%s): ms per frame and M joints/s\n", model.c_str());
    std::printf("%10s %12s %12s %10s %12s %10s %12s %10s %10s\n", "characters", "joints", "cpu 1 thr", "Mj/s",
                "cpu all", "Mj/s", "gpu palette", "Mj/s", "gpu motion");
    for (const PaletteRow& r : rows) {
        if (!r.error.empty()) {
            std::printf("%10u  skipped: %s\n", r.characters, r.error.c_str());
            continue;
        }
        std::printf("%10u %12llu %12.3f %10.1f %12.3f %10.1f %12.3f %10.1f %10.3f\n", r.characters,
                    static_cast<unsigned long long>(r.joints), r.cpuOneThreadMs, jointsPerSecond(r.joints, r.cpuOneThreadMs) * 1e-6,
                    r.cpuAllThreadsMs, jointsPerSecond(r.joints, r.cpuAllThreadsMs) * 1e-6, r.gpuPaletteMs,
                    jointsPerSecond(r.joints, r.gpuPaletteMs) * 1e-6, r.gpuMotionMs);
    }
}

void writePaletteCsv(const std::string& path, const BenchMeta& meta, const std::string& model,
                     const std::vector<PaletteRow>& rows) {
    std::ostringstream file;
    file << "model,characters,joints,status,cpu_threads,cpu_1_thread_palette_ms,cpu_1_thread_joints_per_s,"
            "cpu_all_threads_palette_ms,cpu_all_threads_joints_per_s,gpu_palette_ms,gpu_palette_joints_per_s,"
            "gpu_motion_ms,gpu_clock,frames,warmup,device,driver,commit,date,error\n";
    for (const PaletteRow& r : rows) {
        file << model << ',' << r.characters << ',' << r.joints << ',' << (r.error.empty() ? "ok" : "skipped") << ','
             << r.threads << ',' << r.cpuOneThreadMs << ',' << jointsPerSecond(r.joints, r.cpuOneThreadMs) << ','
             << r.cpuAllThreadsMs << ',' << jointsPerSecond(r.joints, r.cpuAllThreadsMs) << ',' << r.gpuPaletteMs << ','
             << jointsPerSecond(r.joints, r.gpuPaletteMs) << ',' << r.gpuMotionMs << ',' << r.gpuClock << ','
             << meta.frames << ',' << meta.warmup << ",\"" << meta.device << "\",\"" << meta.driver << "\","
             << meta.commit << ',' << meta.date << ",\"" << r.error << "\"\n";
    }
    io::writeFile(path, file.str());
}

void writePaletteJson(const std::string& path, const BenchMeta& meta, const std::string& model,
                      const std::vector<PaletteRow>& rows) {
    nlohmann::json json = benchJsonHeader(meta);
    json["model"] = model;
    json["crowd"] = "mill behaviour: standing, walking, running, crossfading";
    json["cpu_clock"] = "wall clock, median of runs after a warm-up run";
    json["palettes"] = nlohmann::json::array();
    for (const PaletteRow& r : rows) {
        nlohmann::json row;
        row["characters"] = r.characters;
        row["joints"] = r.joints;
        if (!r.error.empty()) {
            row["error"] = r.error;
        } else {
            row["cpu_threads"] = r.threads;
            row["cpu_1_thread_palette_ms"] = r.cpuOneThreadMs;
            row["cpu_1_thread_joints_per_s"] = jointsPerSecond(r.joints, r.cpuOneThreadMs);
            row["cpu_all_threads_palette_ms"] = r.cpuAllThreadsMs;
            row["cpu_all_threads_joints_per_s"] = jointsPerSecond(r.joints, r.cpuAllThreadsMs);
            row["gpu_palette_ms"] = r.gpuPaletteMs;
            row["gpu_palette_joints_per_s"] = jointsPerSecond(r.joints, r.gpuPaletteMs);
            row["gpu_motion_ms"] = r.gpuMotionMs;
            row["gpu_clock"] = r.gpuClock;
        }
        json["palettes"].push_back(row);
    }
    io::writeFile(path, json.dump(2) + "\n");
}

}  // namespace app
