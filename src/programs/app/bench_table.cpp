#include "app/bench_table.h"

#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/number_text.h"
#include "io/output_file.h"

namespace app {
namespace {

const char* const kPasses[] = {"upload", "motion", "cull", "palette", "skin", "copy", "shadow", "draw"};

double passMs(const BenchResult& r, const char* pass) {
    const auto it = r.passes.medianGpuMs.find(pass);
    return it == r.passes.medianGpuMs.end() ? 0.0 : it->second;
}

const BenchResult* find(const std::vector<BenchResult>& results, const std::string& model, const std::string& method,
                        std::uint32_t count) {
    for (const BenchResult& r : results)
        if (r.model == model && r.method == method && r.count == count) return &r;
    return nullptr;
}

}  // namespace

double ratioToStatic(const std::vector<BenchResult>& results, const BenchResult& result) {
    const BenchResult* ceiling = find(results, result.model, "static", result.count);
    if (!ceiling || !ceiling->ok || !result.ok || ceiling->frame.medianFrameMs <= 0.0) return 0.0;
    return result.frame.medianFrameMs / ceiling->frame.medianFrameMs;
}

double skinVerticesPerSecond(const BenchResult& result) {
    const double ms = passMs(result, "skin");
    if (ms <= 0.0 || result.method == "static") return 0.0;
    // The vertices this frame's visible characters have at their levels (culling and LOD shrink the work).
    return result.frame.medianSkinnedVertices / (ms * 1e-3);
}

std::uint64_t memoryBytes(const BenchResult& result) {
    std::uint64_t total = 0;
    for (const crowdgpu::MemoryItem& item : result.frame.memory) total += item.bytes;
    return total;
}

void printTable1(const std::vector<BenchResult>& results, const std::vector<std::string>& models,
                 const std::vector<std::string>& methods, const std::vector<std::uint32_t>& counts) {
    for (const std::string& model : models) {
        std::printf("\nTable 1 (%s): frames per second, median of measured frames\n", model.c_str());
        std::printf("%10s", "characters");
        for (const std::string& method : methods) std::printf(" %15s", method.c_str());
        std::printf("\n");
        for (std::uint32_t count : counts) {
            std::printf("%10u", count);
            for (const std::string& method : methods) {
                const BenchResult* r = find(results, model, method, count);
                if (r && r->ok) std::printf(" %15.1f", r->frame.fps);
                else std::printf(" %15s", "-");
            }
            std::printf("\n");
        }
    }
}

void printPassTable(const std::vector<BenchResult>& results) {
    std::printf("\nPer pass (GPU ms, median) and cost of skinning relative to the static ceiling\n");
    std::printf("%-14s %-16s %8s %9s %9s %7s %8s %8s %8s %8s %8s %8s %8s %8s %9s %9s %10s %22s %8s  %s\n", "model", "method",
                "chars", "frame ms", "p95 ms", "/static", "upload", "motion", "cull", "palette", "skin", "copy", "shadow", "draw", "Gvert/s",
                "cpu anim", "memory", "LOD 0/1/2/impostor", "M tris", "pass clock");
    for (const BenchResult& r : results) {
        if (!r.ok) {
            std::printf("%-14s %-16s %8u  skipped: %s\n", r.model.c_str(), r.method.c_str(), r.count, r.error.c_str());
            continue;
        }
        const std::string lods = std::to_string(static_cast<long>(r.frame.medianVisible[0])) + "/" +
                                 std::to_string(static_cast<long>(r.frame.medianVisible[1])) + "/" +
                                 std::to_string(static_cast<long>(r.frame.medianVisible[2])) + "/" +
                                 std::to_string(static_cast<long>(r.frame.medianImpostors));
                std::printf("%-14s %-16s %8u %9.3f %9.3f %7.2f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %9.2f %9.3f %10s %22s %8.2f  %s\n",
                    r.model.c_str(), r.method.c_str(), r.count, r.frame.medianFrameMs, r.frame.p95FrameMs,
                    ratioToStatic(results, r), passMs(r, "upload"), passMs(r, "motion"), passMs(r, "cull"),
                    passMs(r, "palette"), passMs(r, "skin"),
                    passMs(r, "copy"), passMs(r, "shadow"), passMs(r, "draw"), skinVerticesPerSecond(r) * 1e-9, r.frame.medianAnimateMs,
                    app::formatBytes(memoryBytes(r)).c_str(), lods.c_str(), r.frame.medianTriangles / 1e6,
                    r.passes.passClock.c_str());
    }
}

void writeCsv(const std::string& path, const BenchMeta& meta, const std::vector<BenchResult>& results) {
    std::ostringstream file;
    file << "model,method,characters,vertices,triangles,status,median_frame_ms,p95_frame_ms,fps,ratio_to_static,"
            "gpu_upload_ms,gpu_motion_ms,gpu_cull_ms,gpu_palette_ms,gpu_skin_ms,gpu_copy_ms,gpu_shadow_ms,gpu_draw_ms,"
            "gpu_total_ms,pass_clock,skin_vertices_per_s,"
            "cpu_animate_ms,cpu_record_ms,memory_bytes,frames,warmup,width,height,device,driver,commit,date,"
            "scene,culling,visible_lod0,visible_lod1,visible_lod2,triangles_drawn,animation,shadow_triangles,shadow_impostors,aa,"
            "impostors,gpu_raster_ms,raster,gpu_edge_filter_ms,cpu_drive_ms,cpu_ingest_ms,p95_cpu_ingest_ms,cpu_plan_ms,"
            "p95_cpu_plan_ms\n";
    for (const BenchResult& r : results) {
        file << r.model << ',' << r.method << ',' << r.count << ',' << r.vertices << ',' << r.triangles << ','
             << (r.ok ? "ok" : "skipped") << ',' << r.frame.medianFrameMs << ',' << r.frame.p95FrameMs << ','
             << r.frame.fps << ',' << ratioToStatic(results, r);
        for (const char* pass : kPasses) file << ',' << passMs(r, pass);
        file << ',' << r.passes.medianGpuTotalMs << ',' << r.passes.passClock << ',' << skinVerticesPerSecond(r) << ','
             << r.frame.medianAnimateMs << ',' << r.frame.medianRecordMs << ',' << memoryBytes(r) << ','
             << meta.frames << ',' << meta.warmup << ',' << meta.width << ',' << meta.height << ",\"" << meta.device
             << "\",\"" << meta.driver << "\"," << meta.commit << ',' << meta.date << ',' << r.frame.scene << ",\""
             << r.frame.culling << "\"," << r.frame.medianVisible[0] << ',' << r.frame.medianVisible[1] << ','
             << r.frame.medianVisible[2] << ',' << r.frame.medianTriangles << ",\"" << r.frame.animation << "\","
             << r.frame.medianShadowTriangles << ',' << r.frame.medianShadowImpostors << ',' << r.frame.antiAliasing << ','
             << r.frame.medianImpostors << ',' << passMs(r, "raster") << ',' << r.frame.raster << ','
             << passMs(r, "edge filter") << ',' << r.frame.medianDriveMs << ',' << r.frame.medianIngestMs << ','
             << r.frame.p95IngestMs << ',' << r.frame.medianPlanMs << ',' << r.frame.p95PlanMs << '\n';
    }
    io::writeFile(path, file.str());
}

void writeFrameLog(const std::string& path, const std::vector<BenchResult>& results) {
    // Pass columns: every pass any frame timed, in name order (a pass a frame did not run is 0).
    std::set<std::string> passes;
    for (const BenchResult& r : results)
        for (const FrameStats& frame : r.frame.measured)
            for (const PassTime& pass : frame.gpu) passes.insert(pass.pass);
    std::ostringstream file;
    file << "model,method,characters,frame,scene_seconds,interval_ms,gpu_total_ms";
    for (const std::string& pass : passes) file << ",gpu_" << pass << "_ms";
    file << ",cpu_plan_ms,cpu_animate_ms,cpu_record_ms,visible_lod0,visible_lod1,visible_lod2,triangles,impostors,demoted,"
            "shadow_triangles,shadow_impostors\n";
    for (const BenchResult& r : results) {
        if (!r.ok) continue;
        for (std::size_t i = 0; i < r.frame.measured.size(); ++i) {
            const FrameStats& frame = r.frame.measured[i];
            std::map<std::string, double> ms;
            double total = 0.0;
            for (const PassTime& pass : frame.gpu) ms[pass.pass] += pass.milliseconds, total += pass.milliseconds;
            file << r.model << ',' << r.method << ',' << r.count << ',' << i << ',' << frame.sceneSeconds << ','
                 << frame.intervalMs << ',' << total;
            for (const std::string& pass : passes) file << ',' << ms[pass];
            const crowdgpu::FrameCounts& lods = frame.lods;
            file << ',' << frame.planMs << ',' << frame.animateMs << ',' << frame.recordMs << ',' << lods.characters[0]
                 << ',' << lods.characters[1] << ',' << lods.characters[2] << ','
                 << lods.triangles[0] + lods.triangles[1] + lods.triangles[2] << ',' << lods.impostors << ','
                 << lods.demoted << ',' << lods.shadowTriangles[0] + lods.shadowTriangles[1] + lods.shadowTriangles[2]
                 << ',' << lods.shadowImpostors << '\n';
        }
    }
    io::writeFile(path, file.str());
}

nlohmann::json benchJsonHeader(const BenchMeta& meta) {
    nlohmann::json json;
    json["device"] = meta.device;
    json["driver"] = meta.driver;
    json["commit"] = meta.commit;
    json["date"] = meta.date;
    json["command"] = meta.command;
    return json;
}

void writeBenchJson(const std::string& path, const BenchMeta& meta, const std::vector<BenchResult>& results) {
    nlohmann::json json = benchJsonHeader(meta);
    json["frames"] = meta.frames;
    json["warmup"] = meta.warmup;
    json["size"] = {meta.width, meta.height};
    json["frame_clock"] = "wall clock between frame starts, frames pipelined (2 in flight)";
    json["results"] = nlohmann::json::array();
    for (const BenchResult& r : results) {
        nlohmann::json row;
        row["model"] = r.model;
        row["method"] = r.method;
        row["characters"] = r.count;
        row["vertices"] = r.vertices;
        row["triangles"] = r.triangles;
        row["status"] = r.ok ? "ok" : "skipped";
        if (!r.ok) row["error"] = r.error;
        row["median_frame_ms"] = r.frame.medianFrameMs;
        row["p95_frame_ms"] = r.frame.p95FrameMs;
        row["fps"] = r.frame.fps;
        if (r.frame.frameClock != app::RunSummary{}.frameClock) row["frame_clock"] = r.frame.frameClock;
        row["ratio_to_static"] = ratioToStatic(results, r);
        row["gpu_ms"] = r.passes.medianGpuMs;
        row["gpu_total_ms"] = r.passes.medianGpuTotalMs;
        row["pass_clock"] = r.passes.passClock;
        row["skin_vertices_per_s"] = skinVerticesPerSecond(r);
        row["cpu_drive_ms"] = r.frame.medianDriveMs;    // the world's driver: its own work and its calls
        row["cpu_ingest_ms"] = r.frame.medianIngestMs;  // its calls: spawns, removals, samples handed over
        row["p95_cpu_ingest_ms"] = r.frame.p95IngestMs;
        row["cpu_plan_ms"] = r.frame.medianPlanMs;  // Crowd::advanceTo: the living behaviours' planning
        row["p95_cpu_plan_ms"] = r.frame.p95PlanMs;
        row["cpu_animate_ms"] = r.frame.medianAnimateMs;
        row["cpu_record_ms"] = r.frame.medianRecordMs;
        row["scene"] = r.frame.scene;
        row["culling"] = r.frame.culling;
        row["aa"] = r.frame.antiAliasing;
        row["raster"] = r.frame.raster;
        row["gpu_raster_ms"] = passMs(r, "raster");
        row["gpu_edge_filter_ms"] = passMs(r, "edge filter");  // --aa fxaa
        row["animation"] = r.frame.animation;
        row["median_visible_per_lod"] = {r.frame.medianVisible[0], r.frame.medianVisible[1], r.frame.medianVisible[2]};
        row["median_triangles"] = r.frame.medianTriangles;
        row["median_shadow_triangles"] = r.frame.medianShadowTriangles;
        row["median_shadow_impostors"] = r.frame.medianShadowImpostors;
        row["median_impostors"] = r.frame.medianImpostors;
        row["median_demoted_to_impostors"] = r.frame.medianDemoted;
        row["memory_bytes_per_character"] = r.frame.memoryPerCharacter;
        row["gpu_ms"] = r.frame.medianGpuMs;
        if (r.frame.atlasBakeMs > 0.0) row["impostor_atlas_bake_ms"] = r.frame.atlasBakeMs;
        for (const crowdgpu::MemoryItem& item : r.frame.memory) row["memory_bytes"][item.what] = item.bytes;
        json["results"].push_back(row);
    }
    io::writeFile(path, json.dump(2) + "\n");
}

}  // namespace app
