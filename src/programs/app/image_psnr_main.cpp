// image-psnr: how far one picture is from another, for the benchmark scripts (bench/run_capacity.sh):
// PSNR over the colour channels, the mean squared error and the share of pixels that differ.
#include <cmath>
#include <cstdio>
#include <exception>

#include "app/image_difference.h"
#include "app/png_reader.h"
#include "io/standard_output.h"

int main(int argc, char** argv) {
    io::failOnUnwrittenStandardOutput("image-psnr");
    if (argc != 3) {
        std::fprintf(stderr, "usage: image-psnr A.png B.png\n");
        return 1;
    }
    try {
        const app::Rgba8Image a = app::readPng(argv[1]), b = app::readPng(argv[2]);
        const app::ImageDifference d = app::compareImages(a, b);
        const double pixels = static_cast<double>(a.width) * a.height;
        // Equal pictures have no noise: an infinite ratio, printed as such.
        if (std::isinf(d.psnr)) std::printf("PSNR inf dB, ");
        else std::printf("PSNR %.2f dB, ", d.psnr);
        std::printf("MSE %.3f, %.3f %% of %ux%u pixels differ\n", d.meanSquaredError,
                    pixels > 0 ? 100.0 * static_cast<double>(d.differingPixels) / pixels : 0.0, a.width, a.height);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "image-psnr: %s\n", e.what());
        return 1;
    }
}
