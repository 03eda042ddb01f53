#pragma once
// Turns per-frame statistics into the figures users read: median frame time, fps, per-pass GPU ms.
#include <map>
#include <string>
#include <vector>

#include "app/options.h"
#include "app/crowd_renderer.h"
#include "app/names.h"

namespace app { class HostDevice; }

namespace app {

struct RunSummary {
    std::string scene;
    std::string model;
    std::string method;
    std::string culling;  // "gpu", "cpu", "off", with "LOD on/off"
    std::string animation = "in-place, gpu animation";  // behaviour and animation path
    std::string antiAliasing = "off";  // --aa
    std::string raster = "hardware";   // --raster
    std::uint32_t characters = 0;
    // Medians over the measured frames: visible characters per level of detail, triangles drawn.
    double medianVisible[app::kLodCount] = {};
    double medianTriangles = 0.0;
    double medianSkinnedVertices = 0.0;  // visible characters x their LOD's vertices
    double medianImpostors = 0.0;        // characters drawn at the impostor level
    double medianDemoted = 0.0;          // of those, over the mesh-level cap
    // The shadow pass: mesh casters per shadow level, their triangles, impostors casting a quad.
    double medianShadowCasters[app::kLodCount] = {};
    double medianShadowTriangles = 0.0;
    double medianShadowImpostors = 0.0;
    std::uint32_t frames = 0;
    std::uint32_t measuredFrames = 0;
    double medianFrameMs = 0.0;   // see frameClock
    double p95FrameMs = 0.0;
    // How frame times were measured: the wall clock between frame starts, or, for a run of one
    // measured frame (no interval to measure), that frame's CPU time plus its GPU passes.
    std::string frameClock = "wall clock between frame starts";
    double fps = 0.0;             // 1000 / medianFrameMs
    double medianDriveMs = 0.0;   // CPU: the world's driver (its own work: a replay, a simulation; and its calls)
    double medianIngestMs = 0.0;  // of that, its calls into the crowd (spawns, removals, samples handed over)
    double p95IngestMs = 0.0;
    double medianPlanMs = 0.0;    // CPU: motion planning (segments whose plan ran out)
    double p95PlanMs = 0.0;       // and its 95th percentile: a planning hitch shows here
    double medianAnimateMs = 0.0; // CPU
    double medianRecordMs = 0.0;  // CPU
    std::map<std::string, double> medianGpuMs;  // per pass, from `passClock`
    std::string passClock = "timestamp queries";
    double medianGpuTotalMs = 0.0;
    std::string device;
    std::string driver;
    std::vector<crowdgpu::MemoryItem> memory;
    // Device bytes per character of the crowd, by kind (app::CrowdRenderer::memoryPerCharacter).
    std::map<std::string, double> memoryPerCharacter;
    double atlasBakeMs = 0.0;  // 0: no impostor atlas
    // The measured frames themselves, in order (crowd-bench --frame-log): what the medians summarize.
    std::vector<app::FrameStats> measured;
};

// ", impostors off" or ", impostors below 32 px (mesh capacity 65536)": for the summary's culling line.
std::string impostorSummary(const RenderOptions& options);
// ", shadows off" or ", shadows on (compute raster, 4 cascades)": the same line's shadows.
std::string shadowSummary(const RenderOptions& options);

double median(std::vector<double> values);
double percentile(std::vector<double> values, double fraction);

// Frames before `warmup` are left out of every median.
RunSummary summarize(const std::vector<app::FrameStats>& stats, std::uint32_t warmup);

// The statistics of at most `capacity` frames, the most recent, after leaving out the first `skip`:
// a long run (crowd-render --frames 1000000) summarizes its last frames in bounded memory instead of
// keeping about 220 bytes for every frame.
class RecentFrames {
public:
    RecentFrames(std::size_t capacity, std::uint64_t skip) : capacity_(capacity), skip_(skip) {}
    // Frames in order, as CrowdRenderer::takeStats() hands them over.
    void add(std::vector<app::FrameStats> frames);
    // The kept frames, oldest first.
    std::vector<app::FrameStats> frames() const;

private:
    std::size_t capacity_;
    std::uint64_t skip_;
    std::vector<app::FrameStats> ring_;
    std::size_t next_ = 0;  // where the next frame goes once the ring is full
};

void printSummary(const RunSummary& summary);
// Throws app::Error naming the path when it cannot be written.
void writeJson(const std::string& path, const RunSummary& summary);

}  // namespace app
