#pragma once
// How many skinned-vertex slots the methods are sized for, from the crowd alone (before any device
// object exists: for the memory and storage-range checks; render/draw_lists.h sizes the same).
#include <cstdint>

#include "crowd/crowd.h"

namespace skin {

// Skinned-vertex slots the methods are sized for: `perFrame`, every character at LOD 0 (a frame's
// worst case; with a cap in effect, the cap's characters at the largest LOD 0), and `fixed`, every
// character at every LOD (the static method's slots). `meshCapacity`: the cap in effect (0: none; a
// cap no smaller than the crowd is none).
struct SkinnedCapacity {
    std::uint64_t perFrame = 0;
    std::uint64_t fixed = 0;
    std::uint32_t meshCapacity = 0;
};
SkinnedCapacity skinnedCapacity(const crowd::Crowd& crowd, std::uint32_t meshCapacity);

}  // namespace skin
