#include "options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace {

// The method names of crowdgpu's programs (--method), so a script passes the same word to both.
constexpr std::pair<const char*, crowdgpu::Method> kMethods[] = {
    {"two-pass", crowdgpu::Method::TwoPass},
    {"two-pass-direct", crowdgpu::Method::TwoPassDirect},
    {"vs", crowdgpu::Method::VertexShader},
    {"vs-instanced", crowdgpu::Method::VertexShaderInstanced},
    {"compute", crowdgpu::Method::Compute},
    {"static", crowdgpu::Method::Static},
};

std::uint32_t parseWhole(const std::string& what, const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0 || value > 0xffffffffu)
        throw std::invalid_argument(what + ": '" + text + "' is not a whole number");
    return static_cast<std::uint32_t>(value);
}

double parseSeconds(const std::string& what, const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) || value < 0.0)
        throw std::invalid_argument(what + ": '" + text + "' is not a number of seconds");
    return value;
}

VkExtent2D parseExtent(const std::string& text) {
    VkExtent2D extent{};
    char rest = 0;
    if (std::sscanf(text.c_str(), "%ux%u%c", &extent.width, &extent.height, &rest) != 2 || extent.width == 0 ||
        extent.height == 0)
        throw std::invalid_argument("size: '" + text + "' is not WIDTHxHEIGHT, e.g. 640x360");
    return extent;
}

crowdgpu::Method parseMethod(const std::string& text) {
    for (const auto& [name, method] : kMethods)
        if (text == name) return method;
    throw std::invalid_argument("--method: unknown method '" + text + "'");
}

}  // namespace

const char* usage() {
    return "usage: embed_headless [options] [out-dir] [WIDTHxHEIGHT] [frames]   (defaults: . 640x360 8)\n"
           "  --scene own|paper-fig4|stress  what to draw: the example's own 64 soldiers with its boxes, or the\n"
           "                                 crowd and camera path of crowd-bench --scene paper-fig4 / stress\n"
           "  --count N          characters (default: the scene's, 64 / 10240 / 100000)\n"
           "  --start SECONDS    scene time of the first frame (default 0), as crowd-bench --start\n"
           "  --method NAME      compute (default), two-pass, two-pass-direct, vs, vs-instanced, static\n"
           "  --warmup N         frames drawn before the timed ones (default 0)\n"
           "  --crowd-only       draw only what crowd-render draws (the library's ground and the crowd):\n"
           "                     no boxes, no ID pass\n"
           "  --device NAME      the first device whose name contains NAME\n"
           "CROWDGPU_VALIDATION=1 turns on the Khronos validation layer (synchronization validation too).\n";
}

Options parseOptions(int argc, char** argv) {
    Options options;
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--scene") {
            const std::string name = value();
            if (!parseScene(name, options.scene)) throw std::invalid_argument("--scene: unknown scene '" + name + "'");
        } else if (arg == "--count") {
            options.count = parseWhole(arg, value());
            if (options.count == 0) throw std::invalid_argument("--count: at least 1");
        } else if (arg == "--start") options.start = parseSeconds(arg, value());
        else if (arg == "--method") options.method = parseMethod(value());
        else if (arg == "--warmup") options.warmup = parseWhole(arg, value());
        else if (arg == "--crowd-only") options.crowdOnly = true;
        else if (arg == "--device") options.device = value();
        else if (arg.rfind("--", 0) == 0) throw std::invalid_argument("unknown option '" + arg + "'");
        else if (positional == 0) options.outDir = arg, ++positional;
        else if (positional == 1) options.extent = parseExtent(arg), ++positional;
        else if (positional == 2) options.frames = parseWhole("frames", arg), ++positional;
        else throw std::invalid_argument("one argument too many: '" + arg + "'");
    }
    if (options.frames == 0) throw std::invalid_argument("frames: at least 1");
    if (options.count == 0) options.count = defaultCount(options.scene);
    return options;
}
