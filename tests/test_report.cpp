// The figures crowd-render and crowd-bench report, from hand-made frame statistics.
#include <gtest/gtest.h>

#include "app/report.h"

namespace {

app::FrameStats stats(double intervalMs, double animateMs = 1.0) {
    app::FrameStats result;
    result.intervalMs = intervalMs;
    result.planMs = 0.25;
    result.animateMs = animateMs;
    result.recordMs = 0.5;
    result.gpu = {{"skin", 2.0}, {"draw", 4.0}};
    return result;
}

}  // namespace

TEST(Report, FrameTimeIsTheMedianIntervalBetweenFrameStarts) {
    const app::RunSummary s = app::summarize({stats(0.0), stats(10.0), stats(30.0), stats(20.0)}, 0);
    EXPECT_DOUBLE_EQ(s.medianFrameMs, 20.0);
    EXPECT_DOUBLE_EQ(s.fps, 50.0);
    EXPECT_EQ(s.frameClock, "wall clock between frame starts");
}

TEST(Report, ASingleFrameReportsItsOwnTimeNotZeroFps) {
    // No previous frame, so no interval: the frame's CPU (0.25 + 1 + 0.5 ms) and GPU (2 + 4 ms) time instead.
    const app::RunSummary s = app::summarize({stats(0.0)}, 0);
    EXPECT_DOUBLE_EQ(s.medianFrameMs, 7.75);
    EXPECT_DOUBLE_EQ(s.fps, 1000.0 / 7.75);
    EXPECT_EQ(s.frameClock, "one frame: CPU plan + animate + record + GPU passes");
}

TEST(Report, RecentFramesKeepsTheLastOnesInOrderAfterTheSkippedOnes) {
    app::RecentFrames recent(3, 2);
    recent.add({stats(0.0, 1), stats(1.0, 2), stats(1.0, 3)});
    EXPECT_EQ(recent.frames().size(), 1u);
    recent.add({stats(1.0, 4), stats(1.0, 5)});
    recent.add({});
    recent.add({stats(1.0, 6), stats(1.0, 7)});
    std::vector<double> kept;
    for (const app::FrameStats& f : recent.frames()) kept.push_back(f.animateMs);
    EXPECT_EQ(kept, (std::vector<double>{5, 6, 7}));
}
