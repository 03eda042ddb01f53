// The visibility buffers' resolve over covered tiles (docs/compute-raster.md, "The resolve over covered
// tiles"): the tiles the scan lists are exactly those holding a drawn pixel of the read-back visibility
// buffer (impostors' and meshes'), and the picture drawn over them is the full-screen resolve's.
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/error.h"
#include "render/frame_view.h"
#include "render/visibility_tiles.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
constexpr VkExtent2D kSize{240, 160};

// Tiles (x | y << 16) of `tile` pixels a side holding a drawn word of a visibility buffer, on the CPU.
std::set<std::uint32_t> coveredTiles(const std::vector<std::uint64_t>& visibility, VkExtent2D extent, std::uint32_t tile) {
    std::set<std::uint32_t> tiles;
    for (std::uint32_t y = 0; y < extent.height; ++y)
        for (std::uint32_t x = 0; x < extent.width; ++x)
            if (visibility.at(std::size_t{y} * extent.width + x) != kEmpty) tiles.insert(x / tile | (y / tile) << 16);
    return tiles;
}

// What the scan listed: the header's draw and the tiles it counts.
struct TileList {
    gpu::VisibilityTileList header{};
    std::vector<std::uint32_t> tiles;
};
TileList readTiles(const gpu::VulkanContext& context, const render::VisibilityTiles& tiles) {
    const std::vector<std::uint32_t> words = test::readAll<std::uint32_t>(context, tiles.list(0));
    TileList list;
    std::memcpy(&list.header, words.data(), sizeof list.header);
    const std::size_t first = sizeof list.header / 4;
    EXPECT_LE(first + list.header.instanceCount, words.size()) << "more tiles counted than the list holds";
    for (std::size_t i = first; i < first + list.header.instanceCount && i < words.size(); ++i) list.tiles.push_back(words[i]);
    return list;
}

// Checks one visibility buffer's list against its read-back words: the draw is six vertices an instance,
// an instance a tile, no tile twice, and the tiles are the covered ones, no more and no fewer. Returns
// how many tiles are covered.
std::size_t expectListedTilesAreCovered(const gpu::VulkanContext& context, const render::VisibilityTiles& tiles,
                                        const gpu::Buffer& visibility, const char* what) {
    const std::set<std::uint32_t> covered = coveredTiles(test::readAll<std::uint64_t>(context, visibility), kSize, tiles.tilePixels());
    const TileList list = readTiles(context, tiles);
    EXPECT_EQ(list.header.vertexCount, 6u) << what;
    EXPECT_EQ(list.header.firstVertex, 0u) << what;
    EXPECT_EQ(list.header.firstInstance, 0u) << what;
    const std::set<std::uint32_t> listed(list.tiles.begin(), list.tiles.end());
    EXPECT_EQ(listed.size(), list.tiles.size()) << what << ": a tile listed twice";
    std::size_t missing = 0, extra = 0;
    for (std::uint32_t t : covered) missing += listed.count(t) ? 0 : 1;
    for (std::uint32_t t : listed) extra += covered.count(t) ? 0 : 1;
    const std::uint32_t across = (kSize.width + tiles.tilePixels() - 1) / tiles.tilePixels();
    const std::uint32_t down = (kSize.height + tiles.tilePixels() - 1) / tiles.tilePixels();
    std::printf("%s, %u px tiles: %zu of %u tiles covered, %zu listed; %zu missing, %zu extra\n", what,
                tiles.tilePixels(), covered.size(), across * down, listed.size(), missing, extra);
    EXPECT_EQ(missing, 0u) << what;
    EXPECT_EQ(extra, 0u) << what;
    return covered.size();
}

// Seven soldiers at known places, seen from 8 m above the ground's level: three near ones (about 30 px
// across) drawn as meshes, four far ones (about 6 px) as impostors, all by the compute rasterizers, with
// the resolve's tiles `tilePixels` a side (0: the full-screen resolve).
struct SevenSoldiers {
    SevenSoldiers(const app::HostDevice& device, const model::SkinnedModel& soldier, std::uint32_t tilePixels)
        : crowd(soldier, characters()), renderer(device, crowd, options(tilePixels)) {
        render::Camera camera;
        const float centre = glm::vec3(soldier.poseSphere).y;
        camera.eye = glm::vec3(0.0f, centre + 3.0f, 14.0f);
        camera.target = glm::vec3(0.0f, centre, -2.0f);
        camera.nearPlane = 0.5f;
        camera.farPlane = 100.0f;
        renderer.camera = test::appCamera(camera);
    }
    static std::vector<crowd::Character> characters() {
        std::vector<crowd::Character> out;
        for (int i = 0; i < 7; ++i) {
            crowd::Character c;
            c.position = i < 3 ? glm::vec3(2.5f * float(i - 1), 0.0f, 6.0f - 1.5f * float(i))
                               : glm::vec3(-9.0f + 6.0f * float(i - 3), 0.0f, -22.0f);
            c.heading = 0.6f * float(i);
            c.timeOffset = 0.2f * float(i);
            out.push_back(c);
        }
        return out;
    }
    static test::RendererOptions options(std::uint32_t tilePixels) {
        test::RendererOptions o;
        o.size = kSize;
        o.method = skin::Method::Compute;
        o.cull.impostors = true;
        o.cull.impostorThreshold = 16.0f;
        o.cull.hysteresis = 0.0f;
        o.cull.lodFade = false;  // fading characters stay on the hardware path
        o.framesInFlight = 1;
        o.raster = render::RasterMode::Compute;
        o.resolveTilePixels = tilePixels;
        o.farCrowd = true;  // the far crowd's layer has tiles of its own to check
        return o;
    }
    // Renders the frame at `time` and returns its picture.
    app::Rgba8Image render(double time) {
        renderer.renderFrame(time);
        renderer.finish();
        lods = test::internalCounts(renderer.takeStats().back().lods);
        return renderer.readback();
    }
    crowd::Crowd crowd;
    test::TestRenderer renderer;
    render::LodCounts lods;
};

std::size_t differingPixels(const app::Rgba8Image& a, const app::Rgba8Image& b) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < std::size_t{kSize.width} * kSize.height; ++i) differ += test::pixelWithin(a, b, i, 0) ? 0 : 1;
    return differ;
}

}  // namespace

// The tiles the scan lists (16 and 32 px a side) are exactly those in which the read-back visibility
// buffer holds a drawn word, for the impostors' buffer, the meshes' and the far crowd's layer (three
// of the four impostors are under its 16 px: averaged into it): none missing, none extra, none twice, and
// the indirect draw is six vertices a listed tile. Each buffer covers some tiles, not all. A next frame
// looking away from the crowd lists none.
TEST_F(GpuTest, ResolveTilesAreTheTilesTheRasterizersDrewInto) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    for (std::uint32_t tile : {16u, 32u}) {
        SevenSoldiers scene(*device, soldier, tile);
        scene.render(0.7);
        const frame::CrowdRecorder& recorder = scene.renderer.recorder();
        ASSERT_EQ(scene.lods.impostors, 4u);
        ASSERT_TRUE(recorder.meshesInComputeThisFrame(0));
        const auto meshSplit = test::readAll<gpu::MeshSplit>(*context, recorder.meshRaster()->split()).at(0);
        const auto impostorSplit = test::readAll<gpu::ImpostorSplit>(*context, recorder.impostorRaster()->split()).at(0);
        EXPECT_EQ(meshSplit.computeCount, 3u);
        EXPECT_EQ(impostorSplit.computeCount, 4u);
        EXPECT_EQ(impostorSplit.averagedCount, 3u);
        ASSERT_NE(recorder.impostorRaster()->tiles(), nullptr);
        const render::FarCrowdLayer* far = recorder.impostorRaster()->farLayer();
        ASSERT_NE(far, nullptr);
        ASSERT_NE(far->tiles(), nullptr);
        ASSERT_NE(recorder.meshRaster()->tiles(), nullptr);
        const std::uint32_t all = ((kSize.width + tile - 1) / tile) * ((kSize.height + tile - 1) / tile);
        const std::size_t impostorTiles = expectListedTilesAreCovered(
            *context, *recorder.impostorRaster()->tiles(), recorder.impostorRaster()->visibility(0), "impostors");
        const std::size_t meshTiles = expectListedTilesAreCovered(*context, *recorder.meshRaster()->tiles(),
                                                                  recorder.meshRaster()->visibility(0), "meshes");
        const std::size_t farTiles = expectListedTilesAreCovered(*context, *far->tiles(), far->depth(0), "far crowd");
        EXPECT_GE(impostorTiles, 1u);
        EXPECT_GE(farTiles, 1u);
        EXPECT_GE(meshTiles, 3u);
        EXPECT_LT(impostorTiles, all / 2);
        EXPECT_LT(farTiles, all / 2);
        EXPECT_LT(meshTiles, all / 2);
        // The next frame looks away from everyone: both lists are empty again (each frame starts its own).
        render::Camera away = test::internalCamera(scene.renderer.camera);
        away.target = away.eye + glm::vec3(0.0f, 0.0f, 1.0f);
        scene.renderer.camera = test::appCamera(away);
        scene.render(0.8);
        EXPECT_EQ(expectListedTilesAreCovered(*context, *recorder.impostorRaster()->tiles(),
                                              recorder.impostorRaster()->visibility(0), "impostors, looking away"),
                  0u);
        EXPECT_EQ(readTiles(*context, *recorder.impostorRaster()->tiles()).header.instanceCount, 0u);
        EXPECT_EQ(expectListedTilesAreCovered(*context, *far->tiles(), far->depth(0), "far crowd, looking away"), 0u);
        ASSERT_TRUE(recorder.meshesInComputeThisFrame(0));
        EXPECT_EQ(readTiles(*context, *recorder.meshRaster()->tiles()).header.instanceCount, 0u);
    }
}

// The picture drawn over the listed tiles (16 and 32 px) equals the full-screen resolve's, every pixel
// of every channel, in two frames of the walking soldiers: the tiles hold every covered pixel, and a
// pixel's shading does not depend on which draw covers it.
TEST_F(GpuTest, ResolveOverTilesDrawsTheFullScreenResolvesPicture) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    SevenSoldiers full(*device, soldier, 0);
    SevenSoldiers tiles16(*device, soldier, 16);
    SevenSoldiers tiles32(*device, soldier, 32);
    EXPECT_EQ(full.renderer.recorder().impostorRaster()->tiles(), nullptr);
    for (double time : {0.7, 1.9}) {
        const app::Rgba8Image reference = full.render(time);
        ASSERT_EQ(full.lods.impostors, 4u);
        const app::Rgba8Image a = tiles16.render(time), b = tiles32.render(time);
        const std::size_t differ16 = differingPixels(reference, a), differ32 = differingPixels(reference, b);
        std::printf("t = %.1f s: pixels differing from the full-screen resolve: %zu (16 px tiles), %zu (32 px)\n", time,
                    differ16, differ32);
        EXPECT_EQ(differ16, 0u);
        EXPECT_EQ(differ32, 0u);
        if (differ16 || differ32) test::keepRasterImages("resolve-tiles-" + std::to_string(time), reference, a);
    }
}

// A side the scan cannot take is refused in one line.
TEST_F(GpuTest, ResolveTileSideIsChecked) {
    EXPECT_TRUE(render::isResolveTileSide(16));
    EXPECT_TRUE(render::isResolveTileSide(256));
    EXPECT_FALSE(render::isResolveTileSide(0));
    EXPECT_FALSE(render::isResolveTileSide(24));
    EXPECT_FALSE(render::isResolveTileSide(272));
    try {
        render::VisibilityTiles tiles(*context, 1, 24);
        ADD_FAILURE() << "a 24 px tile was taken";
    } catch (const gpu::Error& e) {
        EXPECT_EQ(std::string(e.what()), "the resolve's tile side must be a multiple of 16 pixels up to 256, not 24");
    }
}
