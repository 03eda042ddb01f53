// The pass-1 texel layout: every (character, vertex) gets one texel, within the device limits.
#include <set>

#include <gtest/gtest.h>

#include "gpu/vulkan_error.h"
#include "skin/skin_target_layout.h"

TEST(SkinTargetLayout, SmallCrowdFitsOneTileOneRowPerCharacter) {
    const skin::SkinTargetLayout layout = skin::planSkinTargets(600, 1024, 16384);
    EXPECT_EQ(layout.width, 600u);
    EXPECT_EQ(layout.rowsPerCharacter, 1u);
    EXPECT_EQ(layout.tileCount, 1u);
    EXPECT_EQ(layout.tileExtent(0).height, 1024u);
}

TEST(SkinTargetLayout, LargeCrowdIsSplitIntoTilesWithinTheLimit) {
    const skin::SkinTargetLayout layout = skin::planSkinTargets(600, 40000, 16384);
    EXPECT_EQ(layout.tileCount, 3u);
    std::uint32_t total = 0;
    for (std::uint32_t t = 0; t < layout.tileCount; ++t) {
        EXPECT_LE(layout.tileExtent(t).height, 16384u);
        total += layout.charactersInTile(t);
    }
    EXPECT_EQ(total, 40000u);
}

TEST(SkinTargetLayout, EveryCharacterVertexHasItsOwnTexel) {
    // A model wider than the limit wraps onto several rows per character.
    const std::uint32_t vertices = 70, characters = 25, limit = 32;
    const skin::SkinTargetLayout layout = skin::planSkinTargets(vertices, characters, limit);
    EXPECT_EQ(layout.rowsPerCharacter, 3u);
    EXPECT_EQ(layout.charactersPerTile, 10u);  // 32 rows / 3 rows per character
    EXPECT_EQ(layout.tileCount, 3u);
    std::set<std::uint64_t> bufferSlots;
    for (std::uint32_t c = 0; c < characters; ++c)
        for (std::uint32_t v = 0; v < vertices; ++v) {
            const std::uint32_t tile = c / layout.charactersPerTile;
            const std::uint32_t row = (c - layout.firstCharacter(tile)) * layout.rowsPerCharacter + v / layout.width;
            EXPECT_LT(row, layout.tileExtent(tile).height);
            EXPECT_LT(v % layout.width, layout.tileExtent(tile).width);
            bufferSlots.insert(static_cast<std::uint64_t>(c) * layout.characterStride() + v);
        }
    EXPECT_EQ(bufferSlots.size(), static_cast<std::size_t>(vertices) * characters);
}

TEST(SkinTargetLayout, ImpossibleInputsAreRejected) {
    EXPECT_THROW(skin::planSkinTargets(0, 10, 16384), gpu::Error);
    EXPECT_THROW(skin::planSkinTargets(10, 0, 16384), gpu::Error);
    EXPECT_THROW(skin::planSkinTargets(100000, 1, 100), gpu::Error);
}
