#include "app/report.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "app/number_text.h"
#include "io/output_file.h"

namespace app {

double median(std::vector<double> values) { return percentile(std::move(values), 0.5); }

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double position = fraction * static_cast<double>(values.size() - 1);
    const auto below = static_cast<std::size_t>(position);
    const std::size_t above = std::min(below + 1, values.size() - 1);
    return values[below] + (values[above] - values[below]) * (position - static_cast<double>(below));
}

RunSummary summarize(const std::vector<app::FrameStats>& stats, std::uint32_t warmup) {
    RunSummary summary;
    summary.frames = static_cast<std::uint32_t>(stats.size());
    // Never leave every frame out: a short run still reports its last frames.
    const std::size_t first = std::min<std::size_t>(warmup, stats.size() > 1 ? stats.size() - 1 : 0);
    std::vector<double> intervals, drive, ingest, plan, animate, record, total, triangles, skinned, impostors, demoted;
    std::vector<double> shadowTriangles, shadowImpostors;
    std::vector<double> visible[app::kLodCount], casters[app::kLodCount];
    std::map<std::string, std::vector<double>> passes;
    for (std::size_t i = first; i < stats.size(); ++i) {
        const app::FrameStats& frame = stats[i];
        if (frame.intervalMs > 0.0) intervals.push_back(frame.intervalMs);
        drive.push_back(frame.driveMs);
        ingest.push_back(frame.ingestMs);
        plan.push_back(frame.planMs);
        animate.push_back(frame.animateMs);
        record.push_back(frame.recordMs);
        double sum = 0.0;
        for (const app::PassTime& pass : frame.gpu) passes[pass.pass].push_back(pass.milliseconds), sum += pass.milliseconds;
        total.push_back(sum);
        for (int l = 0; l < app::kLodCount; ++l) visible[l].push_back(frame.lods.characters[l]);
        triangles.push_back(static_cast<double>(frame.lods.triangles[0] + frame.lods.triangles[1] + frame.lods.triangles[2]));
        skinned.push_back(static_cast<double>(frame.lods.skinnedVertices));
        impostors.push_back(frame.lods.impostors);
        demoted.push_back(frame.lods.demoted);
        for (int l = 0; l < app::kLodCount; ++l) casters[l].push_back(frame.lods.shadowCharacters[l]);
        shadowTriangles.push_back(static_cast<double>(frame.lods.shadowTriangles[0] + frame.lods.shadowTriangles[1] +
                                                      frame.lods.shadowTriangles[2]));
        shadowImpostors.push_back(frame.lods.shadowImpostors);
    }
    for (int l = 0; l < app::kLodCount; ++l) summary.medianShadowCasters[l] = median(casters[l]);
    summary.medianShadowTriangles = median(shadowTriangles);
    summary.medianShadowImpostors = median(shadowImpostors);
    summary.medianImpostors = median(impostors);
    summary.medianDemoted = median(demoted);
    for (int l = 0; l < app::kLodCount; ++l) summary.medianVisible[l] = median(visible[l]);
    summary.medianTriangles = median(triangles);
    summary.medianSkinnedVertices = median(skinned);
    summary.measuredFrames = static_cast<std::uint32_t>(stats.size() - first);
    if (intervals.empty() && !total.empty()) {
        // One frame: no interval between frame starts to measure. Its own time is what it cost.
        summary.frameClock = "one frame: CPU plan + animate + record + GPU passes";
        intervals.push_back(drive.back() + plan.back() + animate.back() + record.back() + total.back());
    }
    summary.medianFrameMs = median(intervals);
    summary.p95FrameMs = percentile(intervals, 0.95);
    summary.fps = summary.medianFrameMs > 0.0 ? 1000.0 / summary.medianFrameMs : 0.0;
    summary.medianDriveMs = median(drive);
    summary.medianIngestMs = median(ingest);
    summary.p95IngestMs = percentile(ingest, 0.95);
    summary.medianPlanMs = median(plan);
    summary.p95PlanMs = percentile(plan, 0.95);
    summary.medianAnimateMs = median(animate);
    summary.medianRecordMs = median(record);
    for (auto& [pass, values] : passes) summary.medianGpuMs[pass] = median(values);
    summary.medianGpuTotalMs = median(total);
    summary.measured.assign(stats.begin() + static_cast<std::ptrdiff_t>(first), stats.end());
    return summary;
}

void RecentFrames::add(std::vector<app::FrameStats> frames) {
    for (app::FrameStats& frame : frames) {
        if (skip_ > 0) {
            --skip_;
        } else if (ring_.size() < capacity_) {
            ring_.push_back(std::move(frame));
        } else if (capacity_ > 0) {
            ring_[next_] = std::move(frame);
            next_ = (next_ + 1) % capacity_;
        }
    }
}

std::vector<app::FrameStats> RecentFrames::frames() const {
    std::vector<app::FrameStats> ordered(ring_.begin() + static_cast<std::ptrdiff_t>(next_), ring_.end());
    ordered.insert(ordered.end(), ring_.begin(), ring_.begin() + static_cast<std::ptrdiff_t>(next_));
    return ordered;
}

std::string impostorSummary(const RenderOptions& options) {
    if (!options.cull.impostors) return ", impostors off";
    char text[128];
    std::snprintf(text, sizeof text, ", impostors below %g px (mesh capacity %u, raster %s)",
                  options.cull.impostorThreshold, options.meshCapacity, crowdgpu::rasterName(options.cull.raster));
    return text;
}

std::string shadowSummary(const RenderOptions& options) {
    if (!options.shadows) return ", shadows off";
    const bool compute = options.cull.shadowRaster == crowdgpu::ShadowRaster::Compute;
    const std::uint32_t cascades = options.cull.shadowCascades;
    return std::string(", shadows on (") + (compute ? "compute" : "hardware") + " raster, " + std::to_string(cascades) +
           (cascades == 1 ? " cascade)" : " cascades)");
}

void printSummary(const RunSummary& s) {
    std::printf("%s: %s x %u, %s, %u frames (%u measured) on %s (%s)\n", s.scene.c_str(), s.model.c_str(),
                s.characters, s.method.c_str(), s.frames, s.measuredFrames, s.device.c_str(), s.driver.c_str());
    std::printf("  drawn: %.0f / %.0f / %.0f characters at LOD 0 / 1 / 2, %.0f impostors (%.0f over the mesh cap), "
                "%.2f M triangles  [culling %s; anti-aliasing %s]\n",
                s.medianVisible[0], s.medianVisible[1], s.medianVisible[2], s.medianImpostors, s.medianDemoted,
                s.medianTriangles / 1e6, s.culling.c_str(), s.antiAliasing.c_str());
    std::printf("  shadow: %.0f / %.0f / %.0f casters at LOD 0 / 1 / 2, %.0f impostors, %.2f M triangles\n",
                s.medianShadowCasters[0], s.medianShadowCasters[1], s.medianShadowCasters[2], s.medianShadowImpostors,
                s.medianShadowTriangles / 1e6);
    if (s.atlasBakeMs > 0.0) std::printf("  impostor atlas baked in %.0f ms\n", s.atlasBakeMs);
    if (!s.memoryPerCharacter.empty()) {
        std::printf("  device bytes per character:");
        for (const auto& [what, bytes] : s.memoryPerCharacter) std::printf(" %s %.0f,", what.c_str(), bytes);
        std::printf("\n");
    }
    std::printf("  frame: median %.3f ms (%.1f fps), p95 %.3f ms  [%s]\n", s.medianFrameMs, s.fps, s.p95FrameMs,
                s.frameClock.c_str());
    std::printf("  cpu:   drive %.3f ms (ingest %.3f, p95 %.3f), plan %.3f ms, animate %.3f ms, record+submit %.3f ms  [%s]\n",
                s.medianDriveMs, s.medianIngestMs, s.p95IngestMs, s.medianPlanMs, s.medianAnimateMs,
                s.medianRecordMs, s.animation.c_str());
    std::printf("  gpu:  ");
    for (const auto& [pass, ms] : s.medianGpuMs) std::printf(" %s %.3f ms,", pass.c_str(), ms);
    std::printf(" total %.3f ms  [%s]\n", s.medianGpuTotalMs, s.passClock.c_str());
}

void writeJson(const std::string& path, const RunSummary& s) {
    nlohmann::json json;
    json["scene"] = s.scene;
    json["model"] = s.model;
    json["culling"] = s.culling;
    json["animation"] = s.animation;
    json["aa"] = s.antiAliasing;
    json["raster"] = s.raster;
    json["median_visible_per_lod"] = {s.medianVisible[0], s.medianVisible[1], s.medianVisible[2]};
    json["median_triangles"] = s.medianTriangles;
    json["median_impostors"] = s.medianImpostors;
    json["median_demoted_to_impostors"] = s.medianDemoted;
    json["median_shadow_casters_per_lod"] = {s.medianShadowCasters[0], s.medianShadowCasters[1], s.medianShadowCasters[2]};
    json["median_shadow_triangles"] = s.medianShadowTriangles;
    json["median_shadow_impostors"] = s.medianShadowImpostors;
    json["memory_bytes_per_character"] = s.memoryPerCharacter;
    if (s.atlasBakeMs > 0.0) json["impostor_atlas_bake_ms"] = s.atlasBakeMs;
    json["method"] = s.method;
    json["characters"] = s.characters;
    json["frames"] = s.frames;
    json["measured_frames"] = s.measuredFrames;
    json["fps"] = s.fps;
    json["median_frame_ms"] = s.medianFrameMs;
    json["p95_frame_ms"] = s.p95FrameMs;
    json["frame_clock"] = s.frameClock;
    json["median_cpu_drive_ms"] = s.medianDriveMs;
    json["median_cpu_ingest_ms"] = s.medianIngestMs;
    json["p95_cpu_ingest_ms"] = s.p95IngestMs;
    json["median_cpu_plan_ms"] = s.medianPlanMs;
    json["p95_cpu_plan_ms"] = s.p95PlanMs;
    json["median_cpu_animate_ms"] = s.medianAnimateMs;
    json["median_cpu_record_ms"] = s.medianRecordMs;
    json["median_gpu_ms"] = s.medianGpuMs;
    json["median_gpu_total_ms"] = s.medianGpuTotalMs;
    json["gpu_clock"] = s.passClock;
    json["device"] = s.device;
    json["driver"] = s.driver;
    for (const crowdgpu::MemoryItem& item : s.memory) json["memory_bytes"][item.what] = item.bytes;
    io::writeFile(path, json.dump(2) + "\n");
}

}  // namespace app
