#pragma once
// The command line the CPU-only benchmarks share (event-bench, world-bench): a crowd's size, the frames
// measured, the thread counts to measure with and the scene time of the first frame.
#include <cstdint>
#include <string>
#include <vector>

namespace app {

struct CpuBenchOptions {
    std::uint32_t count = 0, frames = 0;
    std::vector<unsigned> threads;
    double start = 0.0;
};

// Parses --count N, --frames N, --threads N,... and --start SECONDS over `options` (its values are the
// defaults); --help prints `usage` and exits 0. False with `problem` set (one line) for a bad flag or value.
bool parseCpuBenchOptions(int argc, char** argv, const char* usage, CpuBenchOptions& options, std::string& problem);

}  // namespace app
