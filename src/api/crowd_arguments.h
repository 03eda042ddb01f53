#pragma once
// The ranges of the crowd API's arguments, each checked once, at the door of the C++ API (the C API
// calls it): a value outside its range is Error(InvalidArgument), one line naming the call, the
// argument and the value, thrown before anything changes. docs/embedding.md ("Argument ranges") lists
// them; the inner code (root motion, sampling, planning) never sees a value outside them.
//
// Why these bounds: scene times are doubles, and the crowd is exact and tested up to 1e9 s
// (docs/hardening.md, "Late starts"), where a run may start and then go on (kLargestTime is 1e10 s);
// positions are floats, which at 1e6 m still step in 6 cm; speeds and rates bound how many cycles a
// window of events covers; everything else only needs to be finite and of the right sign.
#include <cstddef>
#include <cstdint>
#include <string>

#include "crowdgpu/crowd.hpp"

namespace crowdgpu::detail {

inline constexpr double kLargestCoordinate = 1e6;  // metres, either way, of a position or a target
inline constexpr double kLargestHeading = 1e6;     // radians, either way
inline constexpr double kLargestRate = 100.0;      // a character's speed, a command's rate
inline constexpr double kLargestScale = 1e3;
inline constexpr double kLargestTint = 1e3;
inline constexpr double kLongestFade = 3600.0;     // seconds of a crossfade (play)

// A scene time (advanceTo, stateAt, jointWorld, events, computePalettes, moveTo, play, FrameView::time):
// finite, within +-kLargestTime.
void checkTime(const char* call, const char* argument, double time);
// Every field of a character entering the crowd (Crowd's constructor, spawn); `who` names it.
void checkCharacter(const char* call, const std::string& who, const Character& character);
// Whether checkCharacter would pass, making no message (a batch checks its entries so, then names a bad one).
bool characterInRange(const Character& character);
// A grid's layout values: count, depth ratio, variations, per-model weights, clips and scales.
void checkGridLayout(const GridLayout& layout);
void checkBehaviour(const char* call, Behaviour behaviour);
// A command's target (moveTo) and rate; play's fade and rate.
void checkMoveTo(float x, float z, double at, float rate);
void checkPlay(double at, float fade, float rate);
// An event window (from, to]: both times in range, from <= to, at most kLargestEventWindow long, and a
// list of characters when there are any.
void checkEventWindow(const std::uint32_t* characters, std::size_t count, double from, double to);

}  // namespace crowdgpu::detail
