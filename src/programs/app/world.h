#pragma once
// The host's world of a program's run (docs/host-driven.md): the crowd the options ask for (the scene's
// grid, or room for a recording's people), the ground it stands on, the bounds its shadows are fitted to,
// and what drives it every frame (a replay, a live population, agents). crowd-render, crowd-bench and
// crowd-view build theirs here, so one command line is one world in each.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <crowdgpu/crowd.hpp>

#include "app/crowd_app.h"
#include "app/crowd_driver.h"
#include "app/options.h"
#include "replay/trajectory.h"

namespace app {

class HostDevice;

struct World {
    std::unique_ptr<replay::Recording> recording;  // --trajectories: the recording its driver replays
    crowdgpu::Crowd crowd;
    std::unique_ptr<CrowdDriver> driver;           // null: the behaviour alone
    std::vector<std::string> notes;                // what a user should know (a recording's reading)
};

// `device` makes the device agents' pass (--agents device; may be null otherwise). Throws app::Error
// naming the flag for what cannot be built (an unreadable recording is its file:line).
World buildWorld(const HostDevice* device, const CrowdModels& models, const SceneOptions& scene,
                 std::uint32_t framesInFlight);

}  // namespace app
