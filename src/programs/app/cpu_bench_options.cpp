#include "app/cpu_bench_options.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace app {
namespace {

// A whole positive number, or false.
bool parseCount(const std::string& text, std::uint32_t& out) {
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, out);
    return error == std::errc() && at == end && out > 0;
}

// "1,4,16": thread counts 1 to 1024.
bool parseThreads(const std::string& text, std::vector<unsigned>& out) {
    out.clear();
    for (std::size_t from = 0; from <= text.size();) {
        const std::size_t comma = std::min(text.find(',', from), text.size());
        std::uint32_t n = 0;
        if (!parseCount(text.substr(from, comma - from), n) || n > 1024) return false;
        out.push_back(n);
        from = comma + 1;
    }
    return true;
}

}  // namespace

bool parseCpuBenchOptions(int argc, char** argv, const char* usage, CpuBenchOptions& o, std::string& problem) {
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::fputs(usage, stdout);
            std::exit(0);
        }
        if (i + 1 >= argc) return problem = flag + ": expected a value", false;
        const std::string value = argv[++i];
        if (flag == "--count" || flag == "--frames") {
            if (!parseCount(value, flag == "--count" ? o.count : o.frames))
                return problem = flag + ": expected a positive whole number, got '" + value + "'", false;
        } else if (flag == "--threads") {
            if (!parseThreads(value, o.threads))
                return problem = "--threads: expected thread counts 1 to 1024 separated by commas, got '" + value + "'", false;
        } else if (flag == "--start") {
            const char* end = value.data() + value.size();
            const auto [at, error] = std::from_chars(value.data(), end, o.start);
            if (error != std::errc() || at != end || !(o.start >= 0.0 && o.start <= 1e6))
                return problem = "--start: expected seconds from 0 to 1e6, got '" + value + "'", false;
        } else {
            return problem = "unknown flag '" + flag + "' (see --help)", false;
        }
    }
    return true;
}

}  // namespace app
