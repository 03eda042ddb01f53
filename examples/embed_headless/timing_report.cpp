#include "timing_report.hpp"

#include <algorithm>

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double position = fraction * static_cast<double>(values.size() - 1);
    const auto below = static_cast<std::size_t>(position);
    const std::size_t above = std::min(below + 1, values.size() - 1);
    return values[below] + (values[above] - values[below]) * (position - static_cast<double>(below));
}

void TimingReport::add(const std::vector<PartTime>& parts, double intervalMs, const crowdgpu::FrameCounts& counts) {
    ++frames_;
    if (intervalMs > 0.0) intervals_.push_back(intervalMs);
    for (int lod = 0; lod < 3; ++lod) drawn_[lod].push_back(counts.characters[lod]);
    if (parts.empty()) return;
    double total = 0.0, crowd = 0.0;
    bool crowdEnded = false;
    for (const PartTime& part : parts) {
        total += part.milliseconds;
        if (!crowdEnded) crowd = total;
        crowdEnded = crowdEnded || part.part == crowdEnd_;
        const auto index = static_cast<std::size_t>(
            std::find(partNames_.begin(), partNames_.end(), part.part) - partNames_.begin());
        if (index == partNames_.size()) {
            partNames_.push_back(part.part);
            partTimes_.emplace_back();
        }
        partTimes_[index].push_back(part.milliseconds);
    }
    crowdGpu_.push_back(crowd);
    gpu_.push_back(total);
}

void TimingReport::print(std::FILE* out) const {
    std::fprintf(out, "timing frames=%u", frames_);
    if (!gpu_.empty())
        std::fprintf(out, " crowd_gpu_median_ms=%.4f crowd_gpu_p95_ms=%.4f gpu_median_ms=%.4f gpu_p95_ms=%.4f",
                     percentile(crowdGpu_, 0.5), percentile(crowdGpu_, 0.95), percentile(gpu_, 0.5),
                     percentile(gpu_, 0.95));
    if (!intervals_.empty())
        std::fprintf(out, " frame_median_ms=%.4f frame_p95_ms=%.4f", percentile(intervals_, 0.5),
                     percentile(intervals_, 0.95));
    std::fprintf(out, " lod_median=%.0f/%.0f/%.0f\n", percentile(drawn_[0], 0.5), percentile(drawn_[1], 0.5),
                 percentile(drawn_[2], 0.5));
    if (gpu_.empty()) {
        std::fprintf(out, "passes_median_ms none (the queue writes no timestamps)\n");
        return;
    }
    std::fprintf(out, "passes_median_ms");
    for (std::size_t i = 0; i < partNames_.size(); ++i)
        std::fprintf(out, " %s=%.4f", partNames_[i].c_str(), percentile(partTimes_[i], 0.5));
    std::fprintf(out, "\n");
}
