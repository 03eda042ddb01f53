#pragma once
// crowd-bench's results and their presentations: the paper's Table 1 layout, per-pass figures,
// CSV and JSON.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/report.h"

namespace app {

struct BenchResult {
    std::string model;
    std::string method;
    std::uint32_t count = 0;
    std::uint32_t vertices = 0;   // per character
    std::uint32_t triangles = 0;  // per character
    bool ok = false;
    std::string error;            // why the configuration did not run
    RunSummary frame;             // pipelined frames: frame time, fps, CPU figures
    RunSummary passes;            // per-pass times (the same run when timestamps are trustworthy)
};

struct BenchMeta {
    std::string device;
    std::string driver;
    std::string commit;
    std::string date;
    std::string command;
    std::uint32_t frames = 0;
    std::uint32_t warmup = 0;
    std::uint32_t width = 0, height = 0;
};

// Frame time of a result over that of "static" for the same model and count (0 when absent).
double ratioToStatic(const std::vector<BenchResult>& results, const BenchResult& result);
// Skinned vertices per second of the skinning pass (0 for methods without one).
double skinVerticesPerSecond(const BenchResult& result);
// Device memory of the result's resources, in bytes.
std::uint64_t memoryBytes(const BenchResult& result);

// Rows: crowd sizes; columns: fps of each method, one block per model (the paper's Table 1).
void printTable1(const std::vector<BenchResult>& results, const std::vector<std::string>& models,
                 const std::vector<std::string>& methods, const std::vector<std::uint32_t>& counts);
// Per configuration: frame ms, ratio to static, GPU ms per pass and its clock, CPU ms, memory.
void printPassTable(const std::vector<BenchResult>& results);

void writeCsv(const std::string& path, const BenchMeta& meta, const std::vector<BenchResult>& results);
// One row per measured frame of every configuration that ran: its scene time, wall-clock interval, GPU
// passes (timestamp queries of the pipelined run, whatever the per-pass clock of the summary), CPU
// phases and counts. The interval of a row is the wall clock since the frame before it started, as
// the summary's frame times are, so its median and p95 are the CSV's.
void writeFrameLog(const std::string& path, const std::vector<BenchResult>& results);
void writeBenchJson(const std::string& path, const BenchMeta& meta, const std::vector<BenchResult>& results);
// What every benchmark JSON starts with: device, driver, commit, date, command.
nlohmann::json benchJsonHeader(const BenchMeta& meta);

}  // namespace app
