// image-downsample: a supersampled render brought down to its size (a box filter in linear light,
// app/image_downsample.h), the reference bench/run_aa.sh measures anti-aliasing against.
#include <charconv>
#include <cstdio>
#include <exception>
#include <string>

#include "app/image_downsample.h"
#include "app/png_reader.h"
#include "io/standard_output.h"

int main(int argc, char** argv) {
    io::failOnUnwrittenStandardOutput("image-downsample");
    if (argc != 4) {
        std::fprintf(stderr, "usage: image-downsample IN.png FACTOR OUT.png\n");
        return 1;
    }
    try {
        const std::string text = argv[2];
        unsigned factor = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), factor);
        if (error != std::errc() || end != text.data() + text.size() || factor < 1 || factor > 64) {
            std::fprintf(stderr, "image-downsample: FACTOR '%s' is not a whole number from 1 to 64\n", argv[2]);
            return 1;
        }
        app::writePng(argv[3], app::boxDownsample(app::readPng(argv[1]), factor));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "image-downsample: %s\n", e.what());
        return 1;
    }
}
