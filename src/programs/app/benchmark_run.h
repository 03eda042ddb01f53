#pragma once
// One benchmark measurement: a crowd rendered for warm-up plus measured frames with one method,
// summarized into medians. Shared by crowd-bench and its tests.
#include <cstdint>
#include <memory>
#include <string>

#include "app/crowd_app.h"
#include "app/options.h"
#include "app/report.h"
#include "app/gpu_timer.h"

namespace app { class HostDevice; }

namespace app {

struct ScenarioOptions {
    // The crowd: a scene preset with its models, culling, LOD and camera path; count as given.
    RenderOptions scene;
    std::uint32_t count = 1;
    crowdgpu::Method method = crowdgpu::Method::TwoPass;
    std::uint32_t warmup = 10;
    std::uint32_t frames = 60;  // measured, after warm-up
    VkExtent2D size{1280, 720};
    std::uint32_t seed = 1;
    app::PassClock passClock = app::PassClock::TimestampQueries;
    // A renderer of these models whose baked impostor atlas this run shares (the bench bakes once).
    const crowdgpu::Renderer* impostorsFrom = nullptr;
};

// Renders the scene's crowd of these models (their default clip, seeded phases) along the scene's
// camera path and summarizes the measured frames. Throws app::Error when the crowd cannot fit the device.
RunSummary runScenario(const app::HostDevice& context, const CrowdModels& models, const ScenarioOptions& options);

// Whether the device's timestamps can be trusted to bracket every pass. lavapipe's do not bracket
// compute dispatches (it reported 0.04 ms for 23 ms of work), so there passes are timed by fences.
bool timestampsBracketAllWork(const app::HostDevice& context);

}  // namespace app
