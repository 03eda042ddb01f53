// The measured frames' times, summarized as crowdgpu's programs summarize theirs (median and 95th
// percentile) and printed as `key=value` lines a script can parse:
//   timing frames=300 crowd_gpu_median_ms=... crowd_gpu_p95_ms=... gpu_median_ms=... gpu_p95_ms=...
//          frame_median_ms=... frame_p95_ms=... lod_median=L0/L1/L2
//   passes_median_ms motion=... cull=... ... draw=... [id=...]
// crowd_gpu: from the frame's start to the end of the part that ends the crowd's work (its colour
// pass); gpu: the whole frame, the host's later passes too; frame: wall clock between frame starts,
// frames pipelined, as crowd-bench's frame time.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <crowdgpu/renderer.hpp>

#include "frame_timer.hpp"

class TimingReport {
public:
    // `crowdEnd`: the part whose mark ends the crowd's work.
    explicit TimingReport(std::string crowdEnd) : crowdEnd_(std::move(crowdEnd)) {}

    // One measured frame: its GPU parts (empty when there are no timestamps), the wall-clock time since
    // the previous frame started (0 for a run's first frame), and what it drew.
    void add(const std::vector<PartTime>& parts, double intervalMs, const crowdgpu::FrameCounts& counts);
    void print(std::FILE* out) const;

private:
    std::string crowdEnd_;
    std::uint32_t frames_ = 0;
    std::vector<double> crowdGpu_, gpu_, intervals_;
    std::vector<double> drawn_[3];                 // characters per level of detail
    std::vector<std::string> partNames_;           // in the order the frames marked them
    std::vector<std::vector<double>> partTimes_;   // by partNames_
};

// The value below which `fraction` of the values lie, linear between neighbours (the programs' rule).
double percentile(std::vector<double> values, double fraction);
