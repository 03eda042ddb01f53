#pragma once
// Turns per-frame statistics into the figures users read: median frame time, fps, per-pass GPU ms.
#include <map>
#include <string>
#include <vector>

#include "frame/crowd_renderer.h"
#include "skin/skinning_method.h"

namespace gpu { class VulkanContext; }

namespace app {

struct RunSummary {
    std::string scene;
    std::string model;
    std::string method;
    std::string culling;  // "gpu", "cpu", "off", with "LOD on/off"
    std::uint32_t characters = 0;
    // Medians over the measured frames: visible characters per level of detail, triangles drawn.
    double medianVisible[LOD_COUNT] = {};
    double medianTriangles = 0.0;
    double medianSkinnedVertices = 0.0;  // visible characters x their LOD's vertices
    std::uint32_t frames = 0;
    std::uint32_t measuredFrames = 0;
    double medianFrameMs = 0.0;   // wall clock between frame starts, after warm-up
    double p95FrameMs = 0.0;
    double fps = 0.0;             // 1000 / medianFrameMs
    double medianAnimateMs = 0.0; // CPU
    double medianRecordMs = 0.0;  // CPU
    std::map<std::string, double> medianGpuMs;  // per pass, from `passClock`
    std::string passClock = "timestamp queries";
    double medianGpuTotalMs = 0.0;
    std::string device;
    std::string driver;
    std::vector<skin::MemoryItem> memory;
};

double median(std::vector<double> values);
double percentile(std::vector<double> values, double fraction);

// Frames before `warmup` are left out of every median.
RunSummary summarize(const std::vector<frame::FrameStats>& stats, std::uint32_t warmup);

void printSummary(const RunSummary& summary);
// Throws gpu::Error naming the path when it cannot be written.
void writeJson(const std::string& path, const RunSummary& summary);

}  // namespace app
