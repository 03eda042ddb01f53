#include "app/image_downsample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "app/error.h"

namespace app {
namespace {

double decode(std::uint8_t level) {
    const double c = level / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

std::uint8_t encodeSrgb(double linear) {
    const double c = linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

Rgba8Image boxDownsample(const Rgba8Image& image, std::uint32_t factor) {
    if (factor == 0 || image.width % factor != 0 || image.height % factor != 0)
        throw Error(std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " pixels do not divide into blocks of " + std::to_string(factor) + "x" + std::to_string(factor));
    std::array<double, 256> linear;
    for (int level = 0; level < 256; ++level) linear[level] = decode(static_cast<std::uint8_t>(level));
    Rgba8Image out{image.width / factor, image.height / factor, {}};
    out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    const double share = 1.0 / (static_cast<double>(factor) * factor);
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            double sum[4] = {};
            for (std::uint32_t dy = 0; dy < factor; ++dy)
                for (std::uint32_t dx = 0; dx < factor; ++dx) {
                    const std::uint8_t* p =
                        &image.pixels[((static_cast<std::size_t>(y) * factor + dy) * image.width + x * factor + dx) * 4];
                    for (int c = 0; c < 3; ++c) sum[c] += linear[p[c]];
                    sum[3] += p[3];  // alpha is a coverage, not light: averaged as it is
                }
            std::uint8_t* q = &out.pixels[(static_cast<std::size_t>(y) * out.width + x) * 4];
            for (int c = 0; c < 3; ++c) q[c] = encodeSrgb(sum[c] * share);
            q[3] = static_cast<std::uint8_t>(std::lround(sum[3] * share));
        }
    return out;
}

}  // namespace app
