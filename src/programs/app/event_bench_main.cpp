// event-bench: what Crowd::events costs (docs/events.md#costs). Builds a crowd of walking soldiers,
// advances it frame by frame at 60 Hz and times one events call per frame for the frame's window over
// every character, on one thread or split over several (each asking for its share at once, as a host
// would), in place and milling. Prints a table: events fired per frame, the median call in ms and per
// character in ns. CPU only: no Vulkan device.
#include <algorithm>
#include <barrier>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"

namespace {

constexpr const char* kUsage = R"(usage: event-bench [--count N] [--frames N] [--threads N,...] [--start SECONDS]
  --count N        walking soldiers in the crowd (default 100000)
  --frames N       60 Hz frames measured, after 10 of warm-up (default 120)
  --threads N,...  threads sharing each frame's call, one row each (default 1)
  --start SECONDS  scene time of the first frame (default 30: the milling crowd under way)
)";

struct Options {
    std::uint32_t count = 100000, frames = 120;
    std::vector<unsigned> threads = {1};
    double start = 30.0;
};

// A whole positive number, or false.
bool parseCount(const std::string& text, std::uint32_t& out) {
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, out);
    return error == std::errc() && at == end && out > 0;
}

bool parseOptions(int argc, char** argv, Options& o, std::string& problem) {
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        }
        if (i + 1 >= argc) return problem = flag + ": expected a value", false;
        const std::string value = argv[++i];
        std::uint32_t n = 0;
        if (flag == "--count" || flag == "--frames") {
            if (!parseCount(value, n)) return problem = flag + ": expected a positive whole number, got '" + value + "'", false;
            (flag == "--count" ? o.count : o.frames) = n;
        } else if (flag == "--threads") {
            o.threads.clear();
            std::size_t from = 0;
            while (from <= value.size()) {
                const std::size_t comma = std::min(value.find(',', from), value.size());
                if (!parseCount(value.substr(from, comma - from), n) || n > 1024)
                    return problem = "--threads: expected thread counts 1 to 1024 separated by commas, got '" + value + "'", false;
                o.threads.push_back(n);
                from = comma + 1;
            }
        } else if (flag == "--start") {
            const char* end = value.data() + value.size();
            const auto [at, error] = std::from_chars(value.data(), end, o.start);
            if (error != std::errc() || at != end || !(o.start >= 0.0 && o.start <= 1e6))
                return problem = "--start: expected seconds from 0 to 1e6, got '" + value + "'", false;
        } else {
            return problem = "unknown flag '" + flag + "' (see --help)", false;
        }
    }
    return true;
}

struct Row {
    const char* behaviour;
    unsigned threads;
    double eventsPerFrame = 0.0, medianMs = 0.0;
    std::uint32_t refusedFrames = 0;  // frames whose window some character could no longer answer
    std::string refusal;              // the last such message
};

// Times `frames` frames' events calls (after 10 of warm-up) for every character of `crowd`, split in
// contiguous shares over `threads` threads that ask at once; the median frame's wall-clock ms.
Row measure(crowdgpu::Crowd& crowd, const char* behaviour, unsigned threads, const Options& o) {
    constexpr std::uint32_t kWarmup = 10;
    constexpr double kFrame = 1.0 / 60.0;
    std::vector<std::uint32_t> everyone(crowd.size());
    for (std::uint32_t c = 0; c < crowd.size(); ++c) everyone[c] = c;
    std::vector<std::vector<crowdgpu::Event>> fired(threads);
    std::vector<std::string> refused(threads);
    double from = 0.0, to = 0.0;
    std::barrier start(static_cast<std::ptrdiff_t>(threads) + 1), done(static_cast<std::ptrdiff_t>(threads) + 1);
    bool stop = false;
    std::vector<std::thread> workers;
    const std::size_t share = (everyone.size() + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            const std::size_t first = std::min(everyone.size(), share * t), last = std::min(everyone.size(), first + share);
            for (;;) {
                start.arrive_and_wait();
                if (stop) return;
                try {
                    crowd.events(everyone.data() + first, last - first, from, to, fired[t]);
                } catch (const crowdgpu::Error& error) {
                    // A character replanned twice within the frame (docs/events.md#not-done-issue-20):
                    // the frame is counted as refused and left out of the timings.
                    fired[t].clear();
                    refused[t] = error.what();
                }
                done.arrive_and_wait();
            }
        });
    Row row{behaviour, threads};
    std::vector<double> ms;
    std::uint64_t events = 0;
    crowd.advanceTo(o.start - kFrame);
    for (std::uint32_t f = 0; f < kWarmup + o.frames; ++f) {
        from = o.start + (static_cast<double>(f) - 1.0) * kFrame;
        to = o.start + static_cast<double>(f) * kFrame;
        crowd.advanceTo(to);
        const auto begin = std::chrono::steady_clock::now();
        start.arrive_and_wait();
        done.arrive_and_wait();
        const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
        const auto failed = std::find_if(refused.begin(), refused.end(), [](const std::string& m) { return !m.empty(); });
        if (failed != refused.end()) {
            ++row.refusedFrames;
            row.refusal = *failed;
            for (std::string& m : refused) m.clear();
            continue;
        }
        if (f < kWarmup) continue;
        ms.push_back(elapsed);
        for (const auto& list : fired) events += list.size();
    }
    stop = true;
    start.arrive_and_wait();
    for (std::thread& w : workers) w.join();
    if (ms.empty()) return row;
    std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
    row.eventsPerFrame = static_cast<double>(events) / static_cast<double>(ms.size());
    row.medianMs = ms[ms.size() / 2];
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    std::string problem;
    if (!parseOptions(argc, argv, o, problem)) {
        std::fprintf(stderr, "event-bench: %s\n", problem.c_str());
        return 1;
    }
    try {
        const auto built = std::chrono::steady_clock::now();
        const crowdgpu::Model soldier = crowdgpu::Model::soldier();
        const double modelMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - built).count();
        std::vector<Row> rows;
        for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::InPlace, crowdgpu::Behaviour::Mill}) {
            crowdgpu::GridLayout layout;
            layout.count = o.count;
            layout.clips = {soldier.findClip("walk")};
            crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, behaviour);
            for (unsigned threads : o.threads) rows.push_back(measure(crowd, crowdgpu::behaviourName(behaviour), threads, o));
        }
        std::printf("Crowd::events for one 60 Hz frame's window, %u soldiers (walk: %u footsteps a cycle), median of %u frames from %.0f s\n",
                    o.count, soldier.eventCount(static_cast<std::uint32_t>(soldier.findClip("walk"))), o.frames, o.start);
        std::printf("(Model::soldier() with its footsteps found: %.1f ms)\n", modelMs);
        std::printf("%-9s %7s %14s %10s %14s %8s\n", "crowd", "threads", "events/frame", "ms/frame", "ns/character", "refused");
        for (const Row& r : rows)
            std::printf("%-9s %7u %14.1f %10.3f %14.1f %8u\n", r.behaviour, r.threads, r.eventsPerFrame, r.medianMs,
                        1e6 * r.medianMs / o.count, r.refusedFrames);
        for (const Row& r : rows)
            if (r.refusedFrames > 0)
                std::printf("refused (%s, %u threads: %u of %u frames, left out): %s\n", r.behaviour, r.threads, r.refusedFrames,
                            o.frames + 10, r.refusal.c_str());
    } catch (const crowdgpu::Error& error) {
        std::fprintf(stderr, "event-bench: %s\n", error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "event-bench: out of host memory for %u soldiers\n", o.count);
        return 1;
    }
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "event-bench: cannot write the table to standard output\n");
        return 1;
    }
    return 0;
}
