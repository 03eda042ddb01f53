#include "api/crowd_arguments.h"

#include <cmath>
#include <cstdio>

#include "crowdgpu/error.hpp"

namespace crowdgpu::detail {
namespace {

// A number as a person writes it: 1e+300, inf, nan, 0.25 (std::to_string prints 1e300 in 301 digits).
std::string text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

// `value` must be finite and within [lo, hi]; `unit` follows the figures ("s", " m", "").
void checkRange(const std::string& what, double value, double lo, double hi, const char* unit = "") {
    if (!std::isfinite(value)) refuse(what + ": " + text(value) + " is not a finite number");
    if (value < lo || value > hi)
        refuse(what + ": " + text(value) + unit + " is outside " + text(lo) + unit + " .. " + text(hi) + unit);
}

// Finite and above zero, at most `hi`.
void checkPositive(const std::string& what, double value, double hi) {
    checkRange(what, value, 0.0, hi);
    if (!(value > 0.0)) refuse(what + ": " + text(value) + " must be above 0");
}

std::string of(const char* call, const char* argument) { return std::string(call) + ": " + argument; }

}  // namespace

void checkTime(const char* call, const char* argument, double time) {
    checkRange(of(call, argument), time, -kLargestTime, kLargestTime, " s");
}

bool characterInRange(const Character& c) {
    const auto in = [](double value, double lo, double hi) { return value >= lo && value <= hi; };  // NaN: no
    bool ok = in(c.phase, -kLargestTime, kLargestTime) && in(c.speed, 0.0, kLargestRate) &&
              in(c.heading, -kLargestHeading, kLargestHeading) && in(c.scale, 0.0, kLargestScale) && c.scale > 0.0f &&
              (c.motion == MotionSource::Behaviour || c.motion == MotionSource::HostSamples ||
               c.motion == MotionSource::DeviceSamples);
    for (int k = 0; k < 3; ++k)
        ok = ok && in(c.position[k], -kLargestCoordinate, kLargestCoordinate) && in(c.tint[k], 0.0, kLargestTint);
    return ok;
}

void checkCharacter(const char* call, const std::string& who, const Character& c) {
    if (characterInRange(c)) return;  // the messages are made for a character that is wrong
    const std::string at = std::string(call) + ": " + who + "'s ";
    if (c.motion != MotionSource::Behaviour && c.motion != MotionSource::HostSamples &&
        c.motion != MotionSource::DeviceSamples)
        refuse(at + "motion: " + std::to_string(static_cast<int>(c.motion)) +
               " is not Behaviour (0), HostSamples (1) or DeviceSamples (2)");
    checkRange(at + "phase", c.phase, -kLargestTime, kLargestTime, " s");
    checkRange(at + "speed", c.speed, 0.0, kLargestRate);
    for (int k = 0; k < 3; ++k)
        checkRange(at + "position[" + std::to_string(k) + "]", c.position[k], -kLargestCoordinate, kLargestCoordinate, " m");
    checkRange(at + "heading", c.heading, -kLargestHeading, kLargestHeading);
    checkPositive(at + "scale", c.scale, kLargestScale);
    for (int k = 0; k < 3; ++k) checkRange(at + "tint[" + std::to_string(k) + "]", c.tint[k], 0.0, kLargestTint);
}

void checkGridLayout(const GridLayout& layout) {
    if (layout.count == 0) refuse("a grid of 0 characters");
    if (layout.motion != MotionSource::Behaviour && layout.motion != MotionSource::HostSamples &&
        layout.motion != MotionSource::DeviceSamples)
        refuse("a grid's motion: " + std::to_string(static_cast<int>(layout.motion)) +
               " is not Behaviour (0), HostSamples (1) or DeviceSamples (2)");
    if (!(layout.depthRatio > 0.0f) || !std::isfinite(layout.depthRatio))
        refuse("a grid's depthRatio must be a positive number, not " + text(layout.depthRatio));
    // A scale of 1 - variation or a tint of 1 - variation must stay above 0 (a character turned inside
    // out, a negative colour).
    checkRange("a grid's scaleVariation", layout.scaleVariation, 0.0, 1.0);
    if (!(layout.scaleVariation < 1.0f)) refuse("a grid's scaleVariation: 1 would scale some characters to 0; it must be below 1");
    checkRange("a grid's tintVariation", layout.tintVariation, 0.0, 1.0);
    double total = 0.0;
    for (std::size_t m = 0; m < layout.weights.size(); ++m) {
        checkRange("a grid's weights[" + std::to_string(m) + "]", layout.weights[m], 0.0, 1e30);
        total += layout.weights[m];
    }
    if (!layout.weights.empty() && !(total > 0.0)) refuse("a grid's weights are all 0: no model has a share");
    for (std::size_t m = 0; m < layout.scales.size(); ++m)
        checkPositive("a grid's scales[" + std::to_string(m) + "]", layout.scales[m], kLargestScale);
    for (std::size_t m = 0; m < layout.clips.size(); ++m)
        if (layout.clips[m] < -1)
            refuse("a grid's clips[" + std::to_string(m) + "]: " + std::to_string(layout.clips[m]) +
                   " is not a clip (-1: the model's walk)");
}

void checkBehaviour(const char* call, Behaviour behaviour) {
    if (behaviour != Behaviour::InPlace && behaviour != Behaviour::March && behaviour != Behaviour::Mill)
        refuse(std::string(call) + ": behaviour " + std::to_string(static_cast<int>(behaviour)) +
               " is not in-place (0), march (1) or mill (2)");
}

void checkMoveTo(float x, float z, double at, float rate) {
    checkRange("moveTo: x", x, -kLargestCoordinate, kLargestCoordinate, " m");
    checkRange("moveTo: z", z, -kLargestCoordinate, kLargestCoordinate, " m");
    checkTime("moveTo", "at", at);
    // A walk at rate 0 would never arrive.
    checkPositive("moveTo: rate", rate, kLargestRate);
}

void checkPlay(double at, float fade, float rate) {
    checkTime("play", "at", at);
    checkRange("play: fade", fade, 0.0, kLongestFade, " s");
    checkRange("play: rate", rate, 0.0, kLargestRate);
}

void checkEventWindow(const std::uint32_t* characters, std::size_t count, double from, double to) {
    if (count > 0 && characters == nullptr) refuse("events: no character list");
    checkTime("events", "from", from);
    checkTime("events", "to", to);
    if (!(to >= from)) refuse("events: the window ends before it starts");
    if (to - from > kLargestEventWindow)
        refuse("events: a window of " + text(to - from) + " s is longer than " + text(kLargestEventWindow) +
               " s (ask for each frame's window as you advance)");
}

}  // namespace crowdgpu::detail
