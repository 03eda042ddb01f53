#pragma once
// crowd-view's command line: crowd-render's flags (same command line, same crowd) plus the
// viewer's own.
#include <string>
#include <vector>

#include "app/options.h"

namespace view {

struct ViewerOptions {
    app::RenderOptions render;  // scene, method, --size (the initial window size), --frames, --validation
    std::string screenshot;     // --screenshot FILE: where F12 (or the scripted run's last frame) writes
    bool ui = true;             // --no-ui: no panel at all (scripted comparisons with crowd-render)
    bool vsync = true;          // --vsync on|off
    // --frames was given: a script. Time advances a fixed 1/60 s per frame (as in crowd-render) and
    // the viewer exits after that many frames, writing --screenshot if given.
    bool scripted = false;
};

// Throws app::Error with a one-line message naming the bad flag or value.
ViewerOptions parseViewerOptions(const std::vector<std::string>& args);

const char* viewerUsage();

}  // namespace view
