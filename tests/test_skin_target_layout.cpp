// The pass-1 texel layout: every skinned vertex slot is exactly one texel, row-major across the
// targets, each target within the device's limits.
#include <set>

#include <gtest/gtest.h>

#include "gpu/vulkan_error.h"
#include "skin/skin_target_layout.h"

namespace {

// The texel (tile, x, y) that slot g lands in, as the shaders compute it.
struct Texel {
    std::uint32_t tile, x, y;
    bool operator<(const Texel& o) const { return std::tie(tile, x, y) < std::tie(o.tile, o.x, o.y); }
};

Texel texelOf(const skin::SkinTargetLayout& layout, std::uint64_t slot) {
    const auto row = static_cast<std::uint32_t>(slot / layout.width);
    return {row / layout.rowsPerTile, static_cast<std::uint32_t>(slot % layout.width), row % layout.rowsPerTile};
}

}  // namespace

TEST(SkinTargetLayout, SmallCapacityFitsOneTargetOfWholeRows) {
    const skin::SkinTargetLayout layout = skin::planSkinTargets(6 * 810, 16384);
    EXPECT_EQ(layout.width, skin::kPreferredTargetWidth);
    EXPECT_EQ(layout.tileCount, 1u);
    EXPECT_EQ(layout.totalRows, (6u * 810u + layout.width - 1) / layout.width);
    EXPECT_GE(static_cast<std::uint64_t>(layout.totalRows) * layout.width, layout.capacity);
}

TEST(SkinTargetLayout, EverySlotIsOneTexelWithinTheLimit) {
    const std::uint32_t limit = 64;
    const std::uint64_t capacity = 40 * 810 + 7;  // not a multiple of a row
    const skin::SkinTargetLayout layout = skin::planSkinTargets(capacity, limit);
    EXPECT_GT(layout.tileCount, 1u);
    std::set<Texel> seen;
    for (std::uint64_t g = 0; g < capacity; ++g) {
        const Texel t = texelOf(layout, g);
        ASSERT_LT(t.tile, layout.tileCount);
        const VkExtent2D extent = layout.tileExtent(t.tile);
        ASSERT_LE(extent.width, limit);
        ASSERT_LE(extent.height, limit);
        ASSERT_LT(t.x, extent.width);
        ASSERT_LT(t.y, extent.height) << "slot " << g;
        ASSERT_TRUE(seen.insert(t).second) << "two slots share a texel at slot " << g;
    }
    // The row-major copy of tile t lands at slot firstRow(t) x width: the tiles tile the buffer.
    for (std::uint32_t t = 1; t < layout.tileCount; ++t)
        EXPECT_EQ(layout.firstRow(t), layout.firstRow(t - 1) + layout.tileExtent(t - 1).height);
}

TEST(SkinTargetLayout, RejectsAZeroLimit) { EXPECT_THROW(skin::planSkinTargets(10, 0), gpu::Error); }
