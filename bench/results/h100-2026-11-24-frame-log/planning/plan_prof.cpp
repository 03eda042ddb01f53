#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/model.hpp"
int main(int argc, char** argv) {
    const unsigned count = argc > 1 ? std::atoi(argv[1]) : 200000;
    const int frames = argc > 2 ? std::atoi(argv[2]) : 120;
    const crowdgpu::Model soldier = crowdgpu::Model::soldier();
    crowdgpu::GridLayout layout;
    layout.count = count;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, crowdgpu::Behaviour::Mill);
    crowd.advanceTo(30.0);
    std::vector<double> ms;
    for (int f = 1; f <= frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        crowd.advanceTo(30.0 + f / 60.0);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    std::printf("%u soldiers milling: advanceTo median %.3f ms p95 %.3f max %.3f (planned %llu)\n", count, ms[ms.size() / 2],
                ms[ms.size() * 95 / 100], ms.back(), 0ull);
}
