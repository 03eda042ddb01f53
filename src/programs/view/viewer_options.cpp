#include "view/viewer_options.h"

#include "app/error.h"

namespace view {

const char* viewerUsage() {
    return R"(crowd-view: the crowd in a window, with a panel to change size, method, model and speed live.

usage: crowd-view [options]        (every crowd-render option below also works: same flags, same crowd)
  --size WxH              initial window size (default 1280x720)
  --vsync on|off          on: FIFO (default); off: MAILBOX, else IMMEDIATE when the surface has them
  --no-ui                 no panel (the picture alone, as crowd-render draws it)
  --screenshot FILE.png   where F12 writes the window's image (default crowd-view-N.png)
  --frames N              script mode: render N frames at fixed 1/60 s steps, write --screenshot if
                          given, and exit; frame N matches crowd-render's frame N
  crowd-render's --out and --json are accepted and ignored.

controls:
  left drag / wheel       orbit / zoom (orbit mode)
  right drag, WASD, Q/E   look, move, down/up (fly mode; shift: faster; wheel: speed)
  C                       toggle orbit / fly
  R                       reset the camera
  F                       follow the character nearest the view centre (again: stop)
  Space                   pause / resume the animation
  H                       hide / show the panel
  F12                     screenshot (PNG of the window, panel included)
  Esc                     quit

)";
}

namespace {

bool framesGiven(const std::vector<std::string>& args) {
    for (const std::string& a : args)
        if (a == "--frames" || a.rfind("--frames=", 0) == 0) return true;
    return false;
}

bool parseOnOff(const std::string& flag, const std::string& value) {
    if (value == "on") return true;
    if (value == "off") return false;
    throw app::Error(flag + ": '" + value + "' is neither on nor off");
}

}  // namespace

ViewerOptions parseViewerOptions(const std::vector<std::string>& args) {
    ViewerOptions options;
    options.render = app::parseRenderOptions(args, [&](const std::string& flag,
                                                       const std::function<std::string()>& value) {
        if (flag == "--screenshot") {
            options.screenshot = value();
            if (options.screenshot.empty()) throw app::Error("--screenshot: empty file name");
        } else if (flag == "--no-ui") options.ui = false;
        else if (flag == "--vsync") options.vsync = parseOnOff(flag, value());
        else return false;
        return true;
    });
    options.scripted = framesGiven(args);
    return options;
}

}  // namespace view
