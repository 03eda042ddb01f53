// world-bench: what the host's world costs the CPU (docs/host-driven.md#costs), the library's calls alone,
// CPU only (no Vulkan device, no renderer, no simulation of the host's): a sample a frame for every
// character of a crowd driven from host arrays (Crowd::drive), and 1 % of a crowd removed and as many
// spawned a frame (remove and spawn batches, then advanceTo), in place and milling, on 1 thread or more
// (crowdgpu::setWorkerThreads). Prints the median and p95 of each call over the frames, in ms.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "app/cpu_bench_options.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"

namespace {

constexpr const char* kUsage = R"(usage: world-bench [--count N] [--frames N] [--threads N,...]
  --count N        characters (default 1000000)
  --frames N       60 Hz frames measured, after 5 of warm-up (default 40)
  --threads N,...  the library's CPU threads, one set of rows each (default 1,16)
  --start SECONDS  scene time of the first frame (default 0; a milling crowd's spawns plan from a
                   closed-form state of their episode, which costs more later on)
)";

using Options = app::CpuBenchOptions;
Options defaultOptions() { return {1000000, 40, {1, 16}, 0.0}; }

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The median and 95th percentile of a call's times.
struct Timing {
    std::vector<double> ms;
    void printRow(const char* what, unsigned threads) {
        std::sort(ms.begin(), ms.end());
        std::printf("%-34s %7u %10.3f %10.3f\n", what, threads, ms[ms.size() / 2], ms[ms.size() * 95 / 100]);
    }
};

constexpr std::uint32_t kWarmup = 5;

// Every character driven from host arrays, walking along x at 1.2 m/s: drive() of a sample each a frame.
void measureDrive(const Options& o, unsigned threads) {
    crowdgpu::GridLayout layout;
    layout.count = o.count;
    layout.motion = crowdgpu::MotionSource::HostSamples;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier()}, layout);
    const std::uint32_t n = crowd.size();
    std::vector<crowdgpu::CharacterHandle> who(n);
    std::vector<double> times(n);
    std::vector<float> x(n), z(n), homeX(n);
    for (std::uint32_t s = 0; s < n; ++s) {
        who[s] = crowd.handle(s);
        const crowdgpu::Character c = crowd.character(s);
        homeX[s] = c.position[0], z[s] = c.position[2];
    }
    Timing drive;
    for (std::uint32_t frame = 0; frame < kWarmup + o.frames; ++frame) {
        const double time = o.start + frame / 60.0;
        for (std::uint32_t s = 0; s < n; ++s) times[s] = time, x[s] = homeX[s] + 1.2f * static_cast<float>(time);
        const auto start = std::chrono::steady_clock::now();
        crowd.drive({who.data(), times.data(), x.data(), z.data(), nullptr, n});
        if (frame >= kWarmup) drive.ms.push_back(millisecondsSince(start));
        crowd.advanceTo(time);
    }
    drive.printRow("drive, a sample each", threads);
}

// 1 % of the crowd leaves and as many enter each frame, as the churn driver does (one remove batch, one
// spawn batch of the leavers' looks), then advanceTo.
void measureChurn(const Options& o, unsigned threads, crowdgpu::Behaviour behaviour) {
    crowdgpu::GridLayout layout;
    layout.count = o.count;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier()}, layout, behaviour);
    std::vector<crowdgpu::CharacterHandle> living;
    std::vector<crowdgpu::Character> looks;
    for (std::uint32_t s = 0; s < crowd.size(); ++s) living.push_back(crowd.handle(s)), looks.push_back(crowd.character(s));
    const std::uint32_t churn = std::max(1u, o.count / 100);
    std::mt19937 random(1);
    std::vector<crowdgpu::CharacterHandle> leaving(churn), entered(churn);
    std::vector<crowdgpu::Character> entering(churn);
    Timing remove, spawn, plan;
    for (std::uint32_t frame = 0; frame < kWarmup + o.frames; ++frame) {
        const double time = o.start + frame / 60.0;
        for (std::uint32_t i = 0; i < churn; ++i) {  // a partial Fisher-Yates: the leavers at the end
            const std::size_t last = living.size() - 1 - i;
            const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, last)(random);
            std::swap(living[pick], living[last]);
            std::swap(looks[pick], looks[last]);
            leaving[i] = living[last], entering[i] = looks[last];
        }
        auto start = std::chrono::steady_clock::now();
        crowd.remove(leaving.data(), churn);
        const double removeMs = millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        crowd.spawn(entering.data(), churn, entered.data());
        const double spawnMs = millisecondsSince(start);
        std::copy(entered.begin(), entered.end(), living.end() - churn);
        start = std::chrono::steady_clock::now();
        crowd.advanceTo(time);
        if (frame < kWarmup) continue;
        remove.ms.push_back(removeMs), spawn.ms.push_back(spawnMs), plan.ms.push_back(millisecondsSince(start));
    }
    const std::string name = crowdgpu::behaviourName(behaviour);
    remove.printRow(("1 % churn, " + name + ": remove").c_str(), threads);
    spawn.printRow(("1 % churn, " + name + ": spawn").c_str(), threads);
    plan.printRow(("1 % churn, " + name + ": advanceTo").c_str(), threads);
}

}  // namespace

int main(int argc, char** argv) {
    Options o = defaultOptions();
    std::string problem;
    if (!app::parseCpuBenchOptions(argc, argv, kUsage, o, problem)) {
        std::fprintf(stderr, "world-bench: %s\n", problem.c_str());
        return 1;
    }
    try {
        std::printf("%u characters, %u frames from %.1f s after %u of warm-up, ms\n", o.count, o.frames, o.start, kWarmup);
        std::printf("%-34s %7s %10s %10s\n", "call", "threads", "median", "p95");
        for (const unsigned threads : o.threads) {
            crowdgpu::setWorkerThreads(threads);
            measureDrive(o, threads);
            measureChurn(o, threads, crowdgpu::Behaviour::InPlace);
            measureChurn(o, threads, crowdgpu::Behaviour::Mill);
        }
    } catch (const crowdgpu::Error& e) {
        std::fprintf(stderr, "world-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
