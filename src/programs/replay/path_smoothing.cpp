#include "replay/path_smoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace replay {
namespace {

// A nanosecond, far below any sampling interval: times such as 2 / 25 - 1 / 25 and 1 / 25 differ in
// their last bit, and a neighbour dropped on one side only would pull a straight walk off its line.
constexpr double kTimeTolerance = 1e-9;

// Sample i of `raw` averaged over neighbours within `reach` seconds on both sides.
Sample smoothedAt(const std::vector<Sample>& raw, std::size_t i, double sigma, double reach) {
    const double t = raw[i].time;
    reach += kTimeTolerance;
    double sum = 0.0, x = 0.0, z = 0.0;
    std::size_t j = i;
    while (j > 0 && t - raw[j - 1].time <= reach) --j;
    for (; j < raw.size() && raw[j].time - t <= reach; ++j) {
        const double u = (raw[j].time - t) / sigma;
        const double w = std::exp(-0.5 * u * u);
        sum += w;
        x += w * raw[j].x;
        z += w * raw[j].z;
    }
    return Sample{t, x / sum, z / sum};
}

void smoothTrack(Track& track, double sigma, double cut, double maxShift, SmoothingReport& report) {
    const std::vector<Sample> raw = track.samples;
    const double first = raw.front().time, last = raw.back().time;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const double reach = std::min({cut, raw[i].time - first, last - raw[i].time});
        track.samples[i] = smoothedAt(raw, i, sigma, reach);
        double deviation = std::hypot(track.samples[i].x - raw[i].x, track.samples[i].z - raw[i].z);
        if (deviation > maxShift) {  // a sharp turn cut: back towards the recording, maxShift from it
            const double keep = maxShift / deviation;
            track.samples[i].x = raw[i].x + (track.samples[i].x - raw[i].x) * keep;
            track.samples[i].z = raw[i].z + (track.samples[i].z - raw[i].z) * keep;
            deviation = maxShift;
        }
        report.meanDeviation += deviation;
        if (deviation > report.maxDeviation) {
            report.maxDeviation = deviation;
            report.maxId = track.id;
            report.maxTime = raw[i].time;
        }
    }
    report.samples += raw.size();
}

}  // namespace

SmoothingReport smoothPaths(Recording& recording, double window, double maxShift) {
    SmoothingReport report;
    report.window = window;
    if (!(window > 0.0)) return report;
    // A moving average over `window` has this standard deviation; the Gaussian has no side lobes
    // that would let a step's sway through at some frequencies, as a box does.
    const double sigma = window / std::sqrt(12.0);
    for (Track& track : recording.tracks) smoothTrack(track, sigma, 3.0 * sigma, maxShift, report);
    if (report.samples > 0) report.meanDeviation /= static_cast<double>(report.samples);
    summarize(recording);
    return report;
}

}  // namespace replay
