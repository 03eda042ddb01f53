// Planning alone, frame by frame: a milling crowd advanced every 1/60 s from 30 s; prints the median and
// every frame (after the first) slower than twice it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/model.hpp"
int main(int argc, char** argv) {
    const unsigned count = argc > 1 ? std::atoi(argv[1]) : 1000000;
    const int frames = argc > 2 ? std::atoi(argv[2]) : 600;
    const crowdgpu::Model soldier = crowdgpu::Model::soldier();
    crowdgpu::GridLayout layout;
    layout.count = count;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, crowdgpu::Behaviour::Mill);
    crowd.advanceTo(30.0);
    crowd.advanceTo(30.0 + 1 / 60.0);
    std::vector<double> ms;
    for (int f = 2; f <= frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        crowd.advanceTo(30.0 + f / 60.0);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    std::printf("%u milling, %zu frames: median %.2f ms, p95 %.2f, max %.2f; over twice the median:", count, ms.size(), median,
                sorted[sorted.size() * 95 / 100], sorted.back());
    int over = 0;
    for (std::size_t i = 0; i < ms.size(); ++i)
        if (ms[i] > 2 * median) std::printf(" %.1f@%zu", ms[i], i + 2), ++over;
    std::printf(" (%d)\n", over);
}
