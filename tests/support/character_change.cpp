#include "support/character_change.h"

#include <algorithm>
#include <cstdlib>

namespace test {

std::vector<bool> characterMask(const app::Rgba8Image& lit, const app::Rgba8Image& dim) {
    std::vector<bool> mask(std::size_t{lit.width} * lit.height);
    for (std::size_t p = 0; p < mask.size(); ++p)
        for (int c = 0; c < 3; ++c) mask[p] = mask[p] || lit.pixels[p * 4 + c] != dim.pixels[p * 4 + c];
    return mask;
}

double characterChange(const app::Rgba8Image& a, const app::Rgba8Image& b, const std::vector<bool>& maskA,
                       const std::vector<bool>& maskB) {
    double sum = 0.0;
    std::size_t pixels = 0;
    for (std::size_t p = 0; p < maskA.size(); ++p) {
        if (!maskA[p] && !maskB[p]) continue;
        ++pixels;
        for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]));
    }
    return sum / (3.0 * static_cast<double>(std::max<std::size_t>(pixels, 1)));
}

}  // namespace test
