// crowd-view: the crowd in a window. The same command line as crowd-render shows the same crowd;
// a panel changes its size, skinning method, model and animation live, and shows what a frame costs.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "crowdgpu/crowd.hpp"
#include "app/host_device.h"
#include "app/error.h"
#include "io/output_file.h"
#include "io/file_size_signal.h"
#include "io/standard_output.h"
#include "view/viewer.h"
#include "view/viewer_options.h"

int main(int argc, char** argv) {
    io::failOnUnwrittenStandardOutput("crowd-view");
    io::failWritesPastTheFileSizeLimit();
    try {
        const view::ViewerOptions options = view::parseViewerOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (options.render.help) return std::printf("%s%s", view::viewerUsage(), app::renderUsage()), 0;
        if (options.render.listDevices) {
            for (const app::DeviceDescription& d : app::listDevices())
                std::printf("%u: %s (%s, %s)\n", d.index, d.name.c_str(), d.type.c_str(), d.driver.c_str());
            return 0;
        }
        crowdgpu::setWorkerThreads(options.render.threads);
        // A script's only output is checked before the window opens.
        if (!options.screenshot.empty()) io::checkWritable(options.screenshot);
        view::Viewer viewer(options);
        return viewer.run();
    } catch (const app::Error& error) {
        std::fprintf(stderr, "crowd-view: %s\n", error.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "crowd-view: out of host memory (try a smaller --count or --size)\n");
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "crowd-view: unexpected error: %s\n", error.what());
        return 2;
    }
}
