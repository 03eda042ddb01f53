#pragma once
// crowd-bench --palette: how fast bone palettes are made for a moving, crossfading crowd (the mill
// behaviour) of growing size, by the CPU jobs on one thread and on every core, and by the GPU's
// motion and palette passes, in milliseconds and joints per second.
#include <cstdint>
#include <string>
#include <vector>

#include "app/bench_table.h"
#include "app/crowd_app.h"
#include "app/gpu_timer.h"

namespace app { class HostDevice; }

namespace app {

struct PaletteRow {
    std::uint32_t characters = 0;
    std::uint64_t joints = 0;          // palettes' joints in all: characters x joints of their model
    unsigned threads = 0;              // the "all threads" run's
    double cpuOneThreadMs = 0.0;       // median over the runs
    double cpuAllThreadsMs = 0.0;
    double gpuPaletteMs = 0.0;         // the palette pass, median over measured frames (every character in view)
    double gpuMotionMs = 0.0;          // the motion pass of the same frames
    std::string gpuClock;
    std::string error;                 // why the row could not be measured, when it could not
};

struct PaletteBenchOptions {
    std::vector<std::uint32_t> counts;
    std::uint32_t frames = 10, warmup = 3, cpuRuns = 3, seed = 1;
    double time = 10.0;  // animation time measured (seconds into the mill)
    app::PassClock clock = app::PassClock::TimestampQueries;
};

std::vector<PaletteRow> runPaletteBench(const app::HostDevice& context, const CrowdModels& models,
                                        const PaletteBenchOptions& options);
void printPaletteTable(const std::vector<PaletteRow>& rows, const std::string& model);
// One row per count, with the JSON's figures (skipped rows: status "skipped" and the reason).
void writePaletteCsv(const std::string& path, const BenchMeta& meta, const std::string& model,
                     const std::vector<PaletteRow>& rows);
// Keys name what they hold: *_palette_ms and *_joints_per_s for each of cpu_1_thread, cpu_all_threads, gpu.
void writePaletteJson(const std::string& path, const BenchMeta& meta, const std::string& model,
                      const std::vector<PaletteRow>& rows);

}  // namespace app
