#pragma once
// The last few seconds of frame statistics, for the panel: averages and the frame-time graph.
#include <cstddef>
#include <deque>
#include <vector>

#include "app/gpu_timer.h"
#include "app/crowd_renderer.h"

namespace view {

class FrameHistory {
public:
    // 240 frames: four seconds at 60 Hz, long enough to see a hitch, short enough to follow a change.
    explicit FrameHistory(std::size_t capacity = 240) : capacity_(capacity) {}

    // A frame's statistics; the oldest frame is dropped beyond the capacity.
    void add(const app::FrameStats& frame);
    // Forgets everything (after a rebuild, so old figures do not blend with the new crowd's).
    void clear() { frames_.clear(); }

    std::size_t size() const { return frames_.size(); }
    // Wall-clock frame times in ms, oldest first (frames with no previous frame are left out).
    std::vector<float> frameMs() const;
    double meanFrameMs() const;
    double fps() const;
    // CPU time per frame: sampling clips and bone matrices, plus recording and submitting.
    double meanCpuMs() const;
    // GPU time per pass, in the order the passes first appear.
    std::vector<app::PassTime> meanGpuMs() const;
    // What the newest frame drew per level of detail (nothing before the first frame).
    crowdgpu::FrameCounts latestLods() const { return frames_.empty() ? crowdgpu::FrameCounts{} : frames_.back().lods; }

private:
    std::size_t capacity_;
    std::deque<app::FrameStats> frames_;
};

}  // namespace view
