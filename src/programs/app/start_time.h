#pragma once
// How late a run may start (--start), and why: time is single precision on the CPU and the GPU, and a
// living crowd replans from 0 s to reach any time.
#include <cstdint>

#include <crowdgpu/crowd.hpp>

namespace app {

// The latest --start. Scene time is a float: at 3600 s it moves in steps of 0.24 ms, so 60 frames a
// second still show 60 different poses; at 1e6 s the step is 62.5 ms and consecutive frames were one
// picture. (Carrying time as double down to the GPU would lift this; it is not done.)
inline constexpr float kMaxStartSeconds = 3600.0f;

// A milling or marching crowd reaches --start by planning every segment of every character from 0 s
// (the same seed gives the same crowd at any frame rate only so): work in proportion to characters x
// seconds (measured on two cores: 1.6 us per character-second, 32 s of planning for 5,555 characters at
// 3600 s). This many character-seconds (100,000 characters at 100 s, 2,777 at the full hour) plan in
// about 15 s on two cores, 2 on sixteen.
inline constexpr double kMaxReplannedCharacterSeconds = 1e7;

// Throws one line naming --start when `start` is beyond either bound for this crowd.
void checkStartTime(float start, std::uint32_t count, crowdgpu::Behaviour behaviour);

}  // namespace app
