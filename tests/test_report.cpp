// The figures crowd-render and crowd-bench report, from hand-made frame statistics.
#include <gtest/gtest.h>

#include "app/report.h"

namespace {

render::FrameStats frame(double intervalMs, double animateMs = 1.0) {
    render::FrameStats stats;
    stats.intervalMs = intervalMs;
    stats.animateMs = animateMs;
    stats.recordMs = 0.5;
    stats.gpu = {{"skin", 2.0}, {"draw", 4.0}};
    return stats;
}

}  // namespace

TEST(Report, FrameTimeIsTheMedianIntervalBetweenFrameStarts) {
    const app::RunSummary s = app::summarize({frame(0.0), frame(10.0), frame(30.0), frame(20.0)}, 0);
    EXPECT_DOUBLE_EQ(s.medianFrameMs, 20.0);
    EXPECT_DOUBLE_EQ(s.fps, 50.0);
    EXPECT_EQ(s.frameClock, "wall clock between frame starts");
}

TEST(Report, ASingleFrameReportsItsOwnTimeNotZeroFps) {
    // No previous frame, so no interval: the frame's CPU (1 + 0.5 ms) and GPU (2 + 4 ms) time instead.
    const app::RunSummary s = app::summarize({frame(0.0)}, 0);
    EXPECT_DOUBLE_EQ(s.medianFrameMs, 7.5);
    EXPECT_DOUBLE_EQ(s.fps, 1000.0 / 7.5);
    EXPECT_EQ(s.frameClock, "one frame: CPU animate + record + GPU passes");
}

TEST(Report, RecentFramesKeepsTheLastOnesInOrderAfterTheSkippedOnes) {
    app::RecentFrames recent(3, 2);
    recent.add({frame(0.0, 1), frame(1.0, 2), frame(1.0, 3)});
    EXPECT_EQ(recent.frames().size(), 1u);
    recent.add({frame(1.0, 4), frame(1.0, 5)});
    recent.add({});
    recent.add({frame(1.0, 6), frame(1.0, 7)});
    std::vector<double> kept;
    for (const render::FrameStats& f : recent.frames()) kept.push_back(f.animateMs);
    EXPECT_EQ(kept, (std::vector<double>{5, 6, 7}));
}
