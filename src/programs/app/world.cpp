#include "app/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/agent_drivers.h"
#include "app/churn_driver.h"
#include "app/error.h"
#include "app/replay_driver.h"
#include "app/terrain_hills.h"
#include "replay/path_smoothing.h"
#include "replay/trajectory_copies.h"
#include "replay/trajectory_reader.h"

namespace app {
namespace {

// Metres an agent may go from where it started (shaders/agent_path.h: a loop of up to 8 m across, more).
constexpr float kAgentReach = 17.0f;

// The half side of the square a grid crowd of this radius (its farthest character from the centre, the
// square's corner) covers: a world box of it frames the crowd as its own bounds do (a box of half side
// `radius` would be sqrt 2 times wider, and the camera that frames it would stand sqrt 2 times farther).
float squareHalfSide(float radius) { return radius / std::sqrt(2.0f); }

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

// The crowd of a recording: room for its most people at once, its extent as the world.
World replayWorld(const CrowdModels& models, const SceneOptions& scene) {
    const WorldOptions& w = scene.world;
    World world{std::make_unique<replay::Recording>(replay::readTrajectories(w.trajectories, w.read)),
                crowdgpu::Crowd({models.models.front()}, {}), nullptr, {}};
    replay::Recording& recording = *world.recording;
    const replay::RecordingInfo& info = recording.info;
    world.notes.push_back(info.path + ": " + info.format + ", " + std::to_string(info.people) + " people, " +
                          std::to_string(info.rows) + " samples, " + format("%.2f s at %.4g fps", info.duration(), info.fps) +
                          ", " + info.units + " (" + replay::provenanceName(info.unitsFrom) + ")");
    if (w.smoothing > 0.0) {
        const replay::SmoothingReport smoothed = replay::smoothPaths(recording, w.smoothing, replay::kDefaultSmoothingShift);
        world.notes.push_back(format("paths smoothed over %.2f s: moved %.2f cm on average, %.2f cm at most",
                                     w.smoothing, 100.0 * smoothed.meanDeviation, 100.0 * smoothed.maxDeviation));
    }
    replay::Tiling tiling;
    std::vector<replay::TrackPlacement> placements;
    if (w.copies > 1) {
        tiling = replay::tileCopies(recording, {w.copies, scene.seed, 2.0});
        placements = tiling.tracks;
    } else {
        placements = replay::placeAsRecorded(recording);
    }
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {std::max(1u, ReplayDriver::mostLive(recording, placements, w.delay))};
    capacity.drivenKeys = crowdgpu::kDrivenKeys;  // everyone enters driven, after the crowd is made
    world.crowd = crowdgpu::Crowd({models.models.front()}, {}, crowdgpu::Behaviour::InPlace, scene.seed, capacity);
    // The world is the copies' extent: shadows fitted to it, the camera framing it.
    const replay::Extent& e = info.extent;
    const std::uint32_t columns = w.copies > 1 ? tiling.columns : 1, rows = w.copies > 1 ? tiling.rows : 1;
    const float lo[3] = {static_cast<float>(e.minX), 0.0f, static_cast<float>(e.minZ)};
    const float hi[3] = {static_cast<float>(e.minX + columns * (e.width() + 2.0) - 2.0), 0.0f,
                         static_cast<float>(e.minZ + rows * (e.depth() + 2.0) - 2.0)};
    if (!e.empty()) world.crowd.setWorldBounds(lo, hi);
    world.crowd.setDrivenTiming({w.delay, 0.5});
    world.driver = std::make_unique<ReplayDriver>(recording, std::move(placements), ReplaySettings{0, w.delay});
    world.notes.push_back(std::to_string(capacity.perModel[0]) + " people at most at once");
    return world;
}

}  // namespace

World buildWorld(const HostDevice* device, const CrowdModels& models, const SceneOptions& scene,
                 std::uint32_t framesInFlight) {
    const WorldOptions& w = scene.world;
    World world = !w.trajectories.empty() ? replayWorld(models, scene)
                                          : World{nullptr, buildCrowd(models, scene), nullptr, {}};
    crowdgpu::Crowd& crowd = world.crowd;
    if (w.trajectories.empty()) {
        float center[3], radius = 0.0f, tallest = 0.0f;
        crowd.bounds(center, radius, tallest);
        if (w.agents != WorldOptions::Agents::None) {
            // The agents leave their grid: the world is its reach (measured once, fixed).
            const float half = squareHalfSide(radius) + kAgentReach;
            const float lo[3] = {center[0] - half, 0.0f, center[2] - half};
            const float hi[3] = {center[0] + half, 0.0f, center[2] + half};
            crowd.setWorldBounds(lo, hi);
            crowd.setDrivenTiming({w.delay, 0.5});
            if (w.agents == WorldOptions::Agents::Host) {
                world.driver = std::make_unique<HostAgents>(crowd);
            } else {
                if (!device) throw Error("--agents device: this program has no device for the agents' pass");
                world.driver = std::make_unique<DeviceAgents>(*device, crowd, framesInFlight);
            }
        } else if (w.churn > 0.0) {
            // Comers take the slots goers left: the grid stays the world.
            const float half = squareHalfSide(radius);
            const float lo[3] = {center[0] - half, 0.0f, center[2] - half};
            const float hi[3] = {center[0] + half, 0.0f, center[2] + half};
            crowd.setWorldBounds(lo, hi);
            world.driver = std::make_unique<ChurnDriver>(w.churn, scene.seed);
        }
    }
    if (w.hills) {
        float center[3], radius = 0.0f, tallest = 0.0f;
        crowd.bounds(center, radius, tallest);
        const TerrainSamples hills = hillsAround(center[0], center[2], radius + 20.0f);
        crowd.setTerrain(hills.heightfield());
        world.notes.push_back(format("terrain: hills, %.0f x %.0f m, %.1f degrees at the steepest", hills.size[0],
                                     hills.size[1], steepestDegrees(hills)));
    }
    return world;
}

}  // namespace app
