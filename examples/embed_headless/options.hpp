// embed_headless's command line:
//   embed_headless [options] [out-dir] [WIDTHxHEIGHT] [frames]
// The three positional arguments are where the images go, their size and how many frames are timed.
// The options pick what to draw and how much of the host's own work goes with it (see usage()).
#pragma once

#include <cstdint>
#include <string>

#include <vulkan/vulkan.h>

#include <crowdgpu/renderer.hpp>

#include "scenes.hpp"

struct Options {
    std::string outDir = ".";
    VkExtent2D extent{640, 360};
    std::uint32_t frames = 8;   // timed, after the warm-up frames
    std::uint32_t warmup = 0;   // drawn first, left out of the timings
    Scene scene = Scene::Own;
    std::uint32_t count = 0;    // characters; 0: the scene's
    double start = 0.0;         // seconds on the scene's clock at the first frame
    crowdgpu::Method method = crowdgpu::Method::Compute;
    // Only what crowd-render draws (the library's ground and the crowd): no boxes, no ground or ID
    // pass of the host's, so its frame costs what the programs' frame costs.
    bool crowdOnly = false;
    std::string device;         // part of the device's name; empty: the first device that fits
};

// Throws std::invalid_argument with a one-line message naming the bad argument.
Options parseOptions(int argc, char** argv);
const char* usage();
