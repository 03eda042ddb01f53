#include "view/frame_history.h"

#include <algorithm>
#include <numeric>

namespace view {

void FrameHistory::add(const app::FrameStats& frame) {
    frames_.push_back(frame);
    while (frames_.size() > capacity_) frames_.pop_front();
}

std::vector<float> FrameHistory::frameMs() const {
    std::vector<float> times;
    for (const app::FrameStats& f : frames_)
        if (f.intervalMs > 0.0) times.push_back(static_cast<float>(f.intervalMs));
    return times;
}

double FrameHistory::meanFrameMs() const {
    const std::vector<float> times = frameMs();
    return times.empty() ? 0.0 : std::accumulate(times.begin(), times.end(), 0.0) / static_cast<double>(times.size());
}

double FrameHistory::fps() const {
    const double ms = meanFrameMs();
    return ms > 0.0 ? 1000.0 / ms : 0.0;
}

double FrameHistory::meanCpuMs() const {
    if (frames_.empty()) return 0.0;
    double sum = 0.0;
    for (const app::FrameStats& f : frames_) sum += f.animateMs + f.recordMs;
    return sum / static_cast<double>(frames_.size());
}

std::vector<app::PassTime> FrameHistory::meanGpuMs() const {
    std::vector<app::PassTime> sums;
    std::vector<std::size_t> counts;
    for (const app::FrameStats& f : frames_) {
        for (const app::PassTime& pass : f.gpu) {
            auto it = std::find_if(sums.begin(), sums.end(),
                                   [&](const app::PassTime& p) { return p.pass == pass.pass; });
            if (it == sums.end()) {
                sums.push_back({pass.pass, 0.0});
                counts.push_back(0);
                it = sums.end() - 1;
            }
            it->milliseconds += pass.milliseconds;
            counts[static_cast<std::size_t>(it - sums.begin())]++;
        }
    }
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i].milliseconds /= static_cast<double>(counts[i]);
    return sums;
}

}  // namespace view
