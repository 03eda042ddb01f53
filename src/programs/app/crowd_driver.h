#pragma once
// What moves the programs' crowds besides their behaviours, each frame before the crowd is planned: a
// recorded crowd replayed (app/replay_driver.h), the benchmarks' populations that come and go
// (app/churn_driver.h) and their agents, simulated on the CPU and handed over in arrays or simulated on
// the GPU by a pass of the host's that writes device samples (app/agent_drivers.h). The frame driver
// (app::CrowdRenderer) calls it; a driver is a host of the library like any other.
#include <chrono>
#include <cstdint>

#include <vulkan/vulkan.h>

#include <crowdgpu/crowd.hpp>
#include <crowdgpu/renderer.hpp>

namespace app {

// Milliseconds `f` takes.
template <class F>
double millisecondsOf(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

class CrowdDriver {
public:
    virtual ~CrowdDriver() = default;
    // Before crowd.advanceTo(time): spawns, removals, samples from the host's memory. Returns the
    // milliseconds its calls into the crowd took (what the library costs the host: its ingest), apart
    // from the driver's own work (reading a recording, simulating agents).
    virtual double update(crowdgpu::Crowd& crowd, double time) = 0;
    // In the frame's command buffer before recordCompute: the host's own pass, when it writes device
    // samples; returns them (null: none this frame). `slot` is the frame slot (its buffers are free).
    virtual const crowdgpu::DeviceSamples* recordBeforeCompute(VkCommandBuffer cmd, std::uint32_t slot, double time) {
        (void)cmd, (void)slot, (void)time;
        return nullptr;
    }
};

}  // namespace app
