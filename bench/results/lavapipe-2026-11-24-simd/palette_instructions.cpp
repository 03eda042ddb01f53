// The CPU palettes of crowd-bench --palette (a milling soldier crowd at 10 s, Crowd::computePalettes on
// the calling thread) without the GPU passes, so that callgrind can count their instructions: a
// load-independent measure on a machine shared with builds. Arguments: characters, timed runs (after
// one warm-up run), and "all" for every core. Built and run by instructions.sh beside it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/crowd_app.h"

int main(int argc, char** argv) {
    const unsigned count = argc > 1 ? static_cast<unsigned>(std::atoi(argv[1])) : 1024;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
    const bool allCores = argc > 3 && std::string(argv[3]) == "all";
    const app::CrowdModels models = app::loadModels("soldier", 1);
    app::SceneOptions scene;  // as crowd-bench --palette builds its crowd (app/palette_bench.cpp)
    scene.count = count;
    scene.seed = 1;
    scene.behaviour = crowdgpu::Behaviour::Mill;
    crowdgpu::Crowd crowd = app::buildCrowd(models, scene);
    crowd.advanceTo(10.0);
    std::vector<float> rows;
    crowd.computePalettes(10.0, rows, allCores);
    double best = 1e30;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        crowd.computePalettes(10.0 + 0.01 * (r + 1), rows, allCores);
        best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    double sum = 0.0;
    for (float f : rows) sum += f;
    std::printf("%u characters, %zu joints: best of %d %.3f ms (%.1f M joints/s); sum of the bones %.6f\n", count,
                rows.size() / 12, runs, best, static_cast<double>(rows.size() / 12) / best * 1e-3, sum);
}
