#pragma once
// One benchmark measurement: a crowd rendered for warm-up plus measured frames with one method,
// summarized into medians. Shared by crowd-bench and its tests.
#include <cstdint>
#include <memory>
#include <string>

#include "app/crowd_app.h"
#include "app/options.h"
#include "app/report.h"
#include "gpu/gpu_timer.h"
#include "model/skinned_model.h"
#include "render/impostor_atlas.h"
#include "skin/skinning_method.h"

namespace gpu { class VulkanContext; }

namespace app {

struct ScenarioOptions {
    // The crowd: a scene preset with its models, culling, LOD and camera path; count as given.
    RenderOptions scene;
    std::uint32_t count = 1;
    skin::Method method = skin::Method::TwoPass;
    std::uint32_t warmup = 10;
    std::uint32_t frames = 60;  // measured, after warm-up
    VkExtent2D size{1280, 720};
    std::uint32_t seed = 1;
    gpu::PassClock passClock = gpu::PassClock::TimestampQueries;
    // An impostor atlas baked before for these models (the bench reuses one across runs).
    std::shared_ptr<const render::ImpostorAtlas> atlas;
};

// Renders the scene's crowd of these models (their default clip, seeded phases) along the scene's
// camera path and summarizes the measured frames. Throws gpu::Error when the crowd cannot fit the device.
RunSummary runScenario(const gpu::VulkanContext& context, const CrowdModels& models, const ScenarioOptions& options);

// Whether the device's timestamps can be trusted to bracket every pass. lavapipe's do not bracket
// compute dispatches (it reported 0.04 ms for 23 ms of work), so there passes are timed by fences.
bool timestampsBracketAllWork(const gpu::VulkanContext& context);

}  // namespace app
