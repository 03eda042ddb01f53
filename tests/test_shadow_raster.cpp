// The shadow map's mesh casters rasterized in compute (render/shadow_raster.h) against the hardware
// rasterizer's map of the same frame: depth texel by texel, and the pictures they shade.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/one_shot_commands.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

// The shadow map's depth, texel by texel (row-major), read back after the frame: its 16-bit unorm
// texels as depths in [0, 1].
std::vector<float> readShadowMap(const gpu::VulkanContext& context, const render::ShadowMap& map) {
    static_assert(render::kShadowFormat == VK_FORMAT_D16_UNORM);
    const std::uint32_t size = map.size();
    gpu::Buffer staging = gpu::createBuffer(context, VkDeviceSize{size} * size * 2, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            gpu::MemoryUse::HostReadback, "test shadow map readback");
    gpu::runOneShot(context, [&](VkCommandBuffer cmd) {
        gpu::imageBarrier(cmd, map.image(), VK_IMAGE_ASPECT_DEPTH_BIT,
                          {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                          {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
        region.imageExtent = {size, size, 1};
        vkCmdCopyImageToBuffer(cmd, map.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &region);
        gpu::imageBarrier(cmd, map.image(), VK_IMAGE_ASPECT_DEPTH_BIT, {VK_PIPELINE_STAGE_2_COPY_BIT, 0},
                          {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    });
    std::vector<std::uint16_t> texels(std::size_t{size} * size);
    std::memcpy(texels.data(), staging.mapped, texels.size() * 2);
    gpu::destroyBuffer(context, staging);
    std::vector<float> depth(texels.size());
    std::transform(texels.begin(), texels.end(), depth.begin(), [](std::uint16_t t) { return t / 65535.0f; });
    return depth;
}

struct ShadowFrame {
    std::vector<float> map;
    app::Rgba8Image picture;
};

// One frame of the renderer with the given shadow raster path: its shadow map and its picture.
ShadowFrame renderWith(test::TestRenderer& renderer, const gpu::VulkanContext& context, render::ShadowRasterPath path,
                       double time) {
    renderer.recorder().setShadowRaster(path);
    renderer.renderFrame(time);
    renderer.finish();
    renderer.takeStats();
    return {readShadowMap(context, renderer.recorder().shadowMap()), renderer.readback()};
}

struct MapComparison {
    std::size_t covered = 0;         // texels either map covers (depth below the far plane)
    std::size_t coverageDiffers = 0; // covered in one map only
    std::size_t depthDiffers = 0;    // covered in both, depths apart by more than the bound
    float largestDepthDifference = 0.0f;
};

MapComparison compareMaps(const std::vector<float>& a, const std::vector<float>& b, float bound) {
    MapComparison c;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool inA = a[i] < 1.0f, inB = b[i] < 1.0f;
        if (!inA && !inB) continue;
        ++c.covered;
        if (inA != inB) {
            ++c.coverageDiffers;
            continue;
        }
        const float d = std::abs(a[i] - b[i]);
        c.largestDepthDifference = std::max(c.largestDepthDifference, d);
        if (d > bound) ++c.depthDiffers;
    }
    return c;
}

// A crowd seen low over its edge with a small map (casters 15 to 40 texels across, as in a large
// scene's 2048 map), for each method that skins into a buffer. The bounds: coverage may differ only
// where a texel centre lies within rounding of a triangle's edge (the hardware snaps vertices to its
// own sub-pixel grid and evaluates edges in its own fixed point): under 0.5 % of covered texels
// (measured on lavapipe: none). Depths within 1e-4 on all but 0.5 % (measured: 0.09 %): the slope bias
// is the hardware's formula, 1.5 times the depth slope, 0.0035 at the median texel here, and the
// slopes the two compute from the same vertices differ in their last bits (the bias the hardware
// applied, over the slope computed here: 1.500 +- 0.003 from the 5th to the 95th percentile); where
// two triangles meet at almost the same depth that can pick the other one (both maps hold 16-bit
// depths, a step of 1.5e-5). The pictures, shaded from the two maps, agree within 2/255 on 99.8 % of
// pixels (measured: 99.95 %). With four cascades (each a quarter of the map) the far ones cover more
// ground a texel, so their slopes a texel, the bias and its last-bit differences are larger: depths
// differ by over 1e-4 on 0.44 % of covered texels, the bound 1 %; coverage stays identical and the
// pictures within 2/255 on 99.96 % of pixels. Packing the two texels of a word the wrong way round
// fails every bound (coverage differs on 46 %).
TEST_F(GpuTest, ComputeShadowMapEqualsTheHardwareOne) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 100;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    for (const std::uint32_t cascades : {1u, 4u}) {
    for (const skin::Method method : {skin::Method::Compute, skin::Method::TwoPass}) {
        SCOPED_TRACE(std::string(skin::methodName(method)) + ", cascades " + std::to_string(cascades));
        test::RendererOptions options;
        options.size = {320, 180};
        options.method = method;
        options.shadowMapSize = 384;
        options.shadowCascades = cascades;
        test::TestRenderer renderer(*device, crowd, options);
        const app::CrowdShape shape = test::shapeOf(crowd);
        renderer.camera.target = shape.center + glm::vec3(0.0f, 1.0f, 0.0f);
        renderer.camera.eye = shape.center + glm::vec3(0.0f, 6.0f, shape.radius + 4.0f);
        const ShadowFrame hardware = renderWith(renderer, *context, render::ShadowRasterPath::Hardware, 0.7);
        ASSERT_TRUE(renderer.recorder().rastersShadowsInCompute() == false);
        const ShadowFrame compute = renderWith(renderer, *context, render::ShadowRasterPath::Compute, 0.7);
        ASSERT_TRUE(renderer.recorder().rastersShadowsInCompute());
        const MapComparison maps = compareMaps(hardware.map, compute.map, 1e-4f);
        const double covered = static_cast<double>(maps.covered);
        std::printf("%s: %zu texels covered, coverage differs on %zu (%.3f %%), depth on %zu (%.3f %%), largest %.3g\n",
                    skin::methodName(method), maps.covered, maps.coverageDiffers, 100.0 * maps.coverageDiffers / covered,
                    maps.depthDiffers, 100.0 * maps.depthDiffers / covered, maps.largestDepthDifference);
        EXPECT_GT(maps.covered, 5000u) << "the casters cover the map";
        EXPECT_LT(maps.coverageDiffers, 0.005 * covered);
        EXPECT_LT(maps.depthDiffers, (cascades == 1 ? 0.005 : 0.01) * covered);
        const double matching = test::fractionOfMatchingPixels(hardware.picture, compute.picture, 2);
        std::printf("%s: pictures match within 2/255 on %.3f %% of pixels\n", skin::methodName(method), 100.0 * matching);
        EXPECT_GT(matching, 0.998);
    }
    }
}

// A map fitted to two soldiers seen close makes their triangles tens to hundreds of texels across: the
// compute pass lists such triangles (records of up to 64 blocks of 16 x 16 texels of their boxes) and
// draws each record with a whole workgroup, skipping the blocks a triangle misses, instead of one thread
// walking the triangle (shadow_raster.comp.glsl; on the H100 that walk made 16 soldiers' shadow pass
// 4.8 ms). The map must still be the hardware one's, with the first test's bounds (measured on
// lavapipe: coverage identical, depths over 1e-4 apart on 0.004 % of covered texels), and the records'
// path must have run (886 records). Skipping blocks by the wrong corner of each fails it (coverage
// differs on 6.8 % of covered texels).
TEST_F(GpuTest, LargeCasterTrianglesKeepTheHardwareMap) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 2;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {320, 180};
    options.method = skin::Method::Compute;
    options.shadowMapSize = 1024;
    test::TestRenderer renderer(*device, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    renderer.camera.target = shape.center + glm::vec3(0.0f, 1.0f, 0.0f);
    renderer.camera.eye = shape.center + glm::vec3(0.0f, 2.0f, shape.radius + 3.0f);
    const ShadowFrame hardware = renderWith(renderer, *context, render::ShadowRasterPath::Hardware, 0.7);
    const ShadowFrame compute = renderWith(renderer, *context, render::ShadowRasterPath::Compute, 0.7);
    ASSERT_TRUE(renderer.recorder().rastersShadowsInCompute());
    const std::uint32_t records =
        test::readAll<std::uint32_t>(*context, renderer.recorder().computeShadowRaster()->largeTriangleRecords())[0];
    const MapComparison maps = compareMaps(hardware.map, compute.map, 1e-4f);
    const double covered = static_cast<double>(maps.covered);
    std::printf("%u records of large triangles' blocks; %zu texels covered, coverage differs on %zu (%.3f %%), depth on %zu (%.3f %%)\n",
                records, maps.covered, maps.coverageDiffers, 100.0 * maps.coverageDiffers / covered, maps.depthDiffers,
                100.0 * maps.depthDiffers / covered);
    EXPECT_GT(records, 100u) << "large triangles were shared out";
    EXPECT_GT(maps.covered, 20000u) << "the casters cover the map";
    EXPECT_LT(maps.coverageDiffers, 0.005 * covered);
    EXPECT_LT(maps.depthDiffers, 0.005 * covered);
    EXPECT_GT(test::fractionOfMatchingPixels(hardware.picture, compute.picture, 2), 0.998);
}

// The impostor-level casters rasterized in compute (render/impostor_shadow_raster.h) against the same
// casters drawn by the graphics pipeline over the copied map (the path before it), every character an
// impostor: 100 soldiers seen low over their edge with a small map (casters 15 to 40 texels across), the
// light's quads cut by the atlas's coverage. With and without impostor-blend (two frames' coverage, or the
// nearest cell's), one and four cascades. Bounds: coverage differs on under 1 % of covered texels (where
// a texel centre's coverage sits at the cut, the hardware interpolating the quad's place in its cell
// from its snapped corners and this pass computing it could differ; measured on lavapipe: none), depths
// within 1e-4 on all but 0.5 % (measured: none, at most two steps of 16 bits apart; the quads face the
// light, so their depth is the centre's), pictures within 2/255 on 99.8 % of pixels (measured: all). A
// quad whose place in its cell is mirrored fails it (coverage differs on 55 % of texels); so does
// drawing no impostor caster (100 %). With 100 casters for 4,096 workgroups each caster is shared among
// 40 of them (impostor_shadow_raster.comp.glsl): every workgroup drawing its caster's first texels
// instead of its own share fails it (coverage differs on 99.5 %).
TEST_F(GpuTest, ComputeImpostorShadowsEqualTheHardwareOnes) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 100;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    std::shared_ptr<const render::ImpostorAtlas> atlas;
    for (const std::uint32_t cascades : {1u, 4u}) {
    for (const bool blend : {true, false}) {
        SCOPED_TRACE("cascades " + std::to_string(cascades) + (blend ? ", impostor-blend" : ", nearest cell"));
        test::RendererOptions options;
        options.size = {320, 180};
        options.method = skin::Method::Compute;
        options.shadowMapSize = 384;
        options.shadowCascades = cascades;
        options.shadowRaster = render::ShadowRasterPath::Compute;
        options.cull.impostors = true;
        // Every character an impostor (the impostor threshold stays under the last mesh level's).
        options.cull.lodThresholds[0] = 200000.0f;
        options.cull.lodThresholds[1] = 150000.0f;
        options.cull.impostorThreshold = 100000.0f;
        options.impostorBlend = blend;
        options.atlas = atlas;
        test::TestRenderer renderer(*device, crowd, options);
        atlas = renderer.impostorAtlas();
        const app::CrowdShape shape = test::shapeOf(crowd);
        renderer.camera.target = shape.center + glm::vec3(0.0f, 1.0f, 0.0f);
        renderer.camera.eye = shape.center + glm::vec3(0.0f, 6.0f, shape.radius + 4.0f);
        ShadowFrame frames[2];
        for (const bool compute : {false, true}) {
            renderer.recorder().setImpostorShadowsInCompute(compute);
            renderer.renderFrame(0.7);
            renderer.finish();
            const std::vector<app::FrameStats> stats = renderer.takeStats();
            EXPECT_EQ(stats.back().lods.characters[0] + stats.back().lods.characters[1] + stats.back().lods.characters[2], 0u)
                << "no mesh in view";
            EXPECT_GT(stats.back().lods.shadowImpostors, 50u) << "impostors cast";
            frames[compute ? 1 : 0] = {readShadowMap(*context, renderer.recorder().shadowMap()), renderer.readback()};
        }
        const MapComparison maps = compareMaps(frames[0].map, frames[1].map, 1e-4f);
        const double covered = static_cast<double>(maps.covered);
        const double matching = test::fractionOfMatchingPixels(frames[0].picture, frames[1].picture, 2);
        std::printf("%zu texels covered, coverage differs on %zu (%.3f %%), depth on %zu (%.3f %%), largest %.3g; "
                    "pictures match within 2/255 on %.3f %% of pixels\n",
                    maps.covered, maps.coverageDiffers, 100.0 * maps.coverageDiffers / covered, maps.depthDiffers,
                    100.0 * maps.depthDiffers / covered, maps.largestDepthDifference, 100.0 * matching);
        EXPECT_GT(maps.covered, 3000u) << "the casters cover the map";
        EXPECT_LT(maps.coverageDiffers, 0.01 * covered);
        EXPECT_LT(maps.depthDiffers, 0.005 * covered);
        EXPECT_GT(matching, 0.998);
    }
    }
}

// The vs baseline skins while it draws: no skinned vertices for the compute rasterizer, so its casters
// stay on the hardware path (and the map is drawn all the same).
TEST_F(GpuTest, TheVsBaselineKeepsItsCastersOnTheHardwarePath) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 16;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::VertexShader;
    options.shadowMapSize = 128;
    options.shadowRaster = render::ShadowRasterPath::Compute;
    test::TestRenderer renderer(*device, crowd, options);
    EXPECT_FALSE(renderer.recorder().rastersShadowsInCompute());
    renderer.renderFrame(0.5);
    renderer.finish();
    const std::vector<float> map = readShadowMap(*context, renderer.recorder().shadowMap());
    EXPECT_GT(std::count_if(map.begin(), map.end(), [](float d) { return d < 1.0f; }), 100) << "casters drawn";
}

}  // namespace
