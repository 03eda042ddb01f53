#include "crowd/farthest_first.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace crowd {
namespace {

// Sizes compare by their bits, as the GPU's histograms rank them: a size is never negative, and
// non-negative floats order as their bits do (the sign bit cleared, as the GPU's key clears it).
std::uint32_t sizeKey(float size) { return std::bit_cast<std::uint32_t>(size) & 0x7fffffffu; }

}  // namespace

std::vector<bool> keepsMesh(std::span<const SizedCharacter> candidates, std::uint32_t capacity) {
    if (candidates.size() <= capacity) return std::vector<bool>(candidates.size(), true);
    std::vector<std::uint32_t> order(candidates.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto before = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint32_t ka = sizeKey(candidates[a].size), kb = sizeKey(candidates[b].size);
        return ka != kb ? ka > kb : candidates[a].character < candidates[b].character;
    };
    std::nth_element(order.begin(), order.begin() + capacity, order.end(), before);
    std::vector<bool> kept(candidates.size(), false);
    for (std::uint32_t i = 0; i < capacity; ++i) kept[order[i]] = true;
    return kept;
}

}  // namespace crowd
