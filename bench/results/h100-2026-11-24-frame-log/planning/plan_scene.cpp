// Planning alone for a scene's crowd (crowd-bench's --scene stress --behaviour mill), frame by frame.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include "app/crowd_app.h"
#include "app/options.h"
int main(int argc, char** argv) {
    const std::string count = argc > 1 ? argv[1] : "1000000";
    const int frames = argc > 2 ? std::atoi(argv[2]) : 600;
    const double start = argc > 3 ? std::atof(argv[3]) : 30.0;
    app::RenderOptions options = app::parseRenderOptions({"--scene", "stress", "--count", count, "--behaviour", "mill"}, nullptr);
    const app::CrowdModels models = app::loadModels(options.scene.model, options.scene.seed, nullptr, "", options.scene.props);
    crowdgpu::Crowd crowd = app::buildCrowd(models, options.scene);
    crowd.advanceTo(start);
    crowd.advanceTo(start + 1 / 60.0);
    std::vector<double> ms;
    for (int f = 2; f <= frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        crowd.advanceTo(start + f / 60.0);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    std::printf("stress %s milling from %.0f s, %zu frames: median %.2f ms, p95 %.2f, max %.2f; over twice the median:",
                count.c_str(), start, ms.size(), median, sorted[sorted.size() * 95 / 100], sorted.back());
    int over = 0;
    for (std::size_t i = 0; i < ms.size(); ++i)
        if (ms[i] > 2 * median) std::printf(" %.1f@%zu", ms[i], i + 2), ++over;
    std::printf(" (%d)\n", over);
}
