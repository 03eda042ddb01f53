#pragma once
// Small, portable random variation from a seed: the same seed gives the same numbers on every
// platform and compiler, which std:: distributions do not promise.
#include <cstdint>

namespace model {

// The seed the characters are built with by default: it gives the reference proportions.
constexpr std::uint32_t kReferenceSeed = 1;

// A value in [-1, 1] from a seed and a salt naming what it varies (one salt per proportion).
inline float seededUnit(std::uint32_t seed, std::uint32_t salt) {
    std::uint32_t x = seed * 0x9E3779B9u ^ (salt + 1u) * 0x85EBCA6Bu;
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return static_cast<float>(x >> 8) / 8388607.5f - 1.0f;  // 24 bits map exactly onto floats
}

// A scale factor within 1 ± amplitude; exactly 1 for the reference seed, so the default
// characters have the sizes their documentation states.
inline float seededScale(std::uint32_t seed, std::uint32_t salt, float amplitude) {
    return seed == kReferenceSeed ? 1.0f : 1.0f + amplitude * seededUnit(seed, salt);
}

}  // namespace model
