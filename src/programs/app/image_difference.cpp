#include "app/image_difference.h"

#include <cmath>
#include <limits>
#include <string>

#include "app/error.h"

namespace app {

ImageDifference compareImages(const app::Rgba8Image& a, const app::Rgba8Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw app::Error("the pictures differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
    const std::uint64_t pixels = std::uint64_t{a.width} * a.height;
    double squares = 0.0;
    ImageDifference d;
    for (std::uint64_t p = 0; p < pixels; ++p) {
        bool differs = false;
        for (int k = 0; k < 3; ++k) {
            const int e = int{a.pixels[p * 4 + k]} - int{b.pixels[p * 4 + k]};
            squares += static_cast<double>(e * e);
            differs = differs || e != 0;
        }
        d.differingPixels += differs ? 1u : 0u;
    }
    d.meanSquaredError = pixels > 0 ? squares / static_cast<double>(pixels * 3) : 0.0;
    d.psnr = d.meanSquaredError > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / d.meanSquaredError)
                                      : std::numeric_limits<double>::infinity();
    return d;
}

}  // namespace app
