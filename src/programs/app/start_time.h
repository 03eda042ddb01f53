#pragma once
// How late a run may start (--start, in crowd-render, crowd-bench and crowd-view). Scene time is a
// double on the CPU and reaches the GPU relative to an epoch near the frame's time (crowd/epoch.h), and
// a marching or milling crowd goes straight to the episode holding any time, whose start is closed form
// (crowd/behaviours.h). So a late start plans what an early one does, and consecutive frames at 60 fps
// differ as they do at 0 s, in every scene.
#include <string>

namespace app {

// 31 years of scene time: tests/test_late_start.cpp renders there, frame by frame.
inline constexpr double kMaxStartSeconds = 1e9;

// --start's value: seconds in 0..kMaxStartSeconds. Throws one line naming `flag` otherwise.
double parseStartSeconds(const std::string& flag, const std::string& text);

}  // namespace app
