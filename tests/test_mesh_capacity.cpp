// The mesh-level cap (--mesh-capacity) demotes the smallest on screen first (crowd/farthest_first.h):
// the rule against a hand-ranked case; a hand-built row of soldiers at known distances, cut by several
// capacities (between coarse size buckets, inside one, through an exact tie), on the GPU against the
// ranking computed here and against the CPU reference; the cut along a camera path against the rule
// applied to the candidates and sizes the GPU listed; and a rendered crowd whose near field must not
// change when the cap demotes half of its meshes.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include "app/crowd_app.h"
#include "app/crowd_renderer.h"
#include "crowd/cull_reference.h"
#include "crowd/farthest_first.h"
#include "app/camera_path.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr VkExtent2D kImage{192, 192};

// The coarse size bucket of the GPU's first histogram: the float's sign, exponent and top mantissa bits.
std::uint32_t coarseBucket(float size) { return std::bit_cast<std::uint32_t>(size) >> MESH_CUT_FINE_BITS; }

// A camera at the height of the soldiers' pose-sphere centres, looking along -z.
render::Camera rowCamera(const model::SkinnedModel& soldier) {
    render::Camera camera;
    camera.eye = glm::vec3(0.0f, soldier.poseSphere.y, 0.0f);
    camera.target = camera.eye + glm::vec3(0.0f, 0.0f, -1.0f);
    return camera;
}

// The distance at which a soldier's pose sphere is `pixels` across in kImage.
float distanceForSize(const model::SkinnedModel& soldier, const render::Camera& camera, float pixels) {
    const float focal = static_cast<float>(kImage.height) / (2.0f * std::tan(0.5f * camera.verticalFov));
    return 2.0f * soldier.poseSphere.w * focal / pixels;
}

// A soldier whose pose-sphere centre is `distance` from the camera (heading 0, scale 1), `angle`
// radians to the right of the view direction.
crowd::Character soldierAt(const model::SkinnedModel& soldier, float distance, float angle) {
    crowd::Character c;
    const glm::vec3 centre = distance * glm::vec3(std::sin(angle), 0.0f, -std::cos(angle));
    c.position = centre - glm::vec3(soldier.poseSphere.x, 0.0f, soldier.poseSphere.z);
    return c;
}

// Sizes, in pixels, of the row's soldiers in front of the camera. The cluster sits in the middle of
// one coarse bucket (32 x (1 + 64.5 / 128) px, the bucket [48, 48.25) px): P, Q and the tied pair
// T1 = T2 a few hundredths of a pixel apart, so a cut inside it needs the fine histogram and a cut
// through the pair needs the tie rule. The spread sits in other coarse buckets, a factor 1.25 apart.
constexpr float kClusterSize = 32.0f * (1.0f + 64.5f / 128.0f);
const float kClusterFactors[] = {1.0004f, 1.0f, 0.9996f, 0.9996f};  // P, Q, T1, T2
constexpr int kSpreadSteps = 6;                                        // 1.25^-6 .. 1.25^6, but not 1.25^0
constexpr float kBehind = 3.14159265f;                                 // an angle: behind the camera

// The row, smallest first: characters in index order get larger, so the order of the atomics (about
// the index order) would keep the farthest. Two soldiers behind the camera are culled (shadows off),
// so fewer qualify for a mesh level than the crowd holds.
std::vector<crowd::Character> buildRow(const model::SkinnedModel& soldier, const render::Camera& camera) {
    std::vector<float> sizes;
    for (int k = -kSpreadSteps; k <= kSpreadSteps; ++k)
        if (k != 0) sizes.push_back(kClusterSize * std::pow(1.25f, static_cast<float>(k)));
    for (float f : kClusterFactors) sizes.push_back(kClusterSize * f);
    std::sort(sizes.begin(), sizes.end());
    std::vector<crowd::Character> row;
    crowd::Character previous;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        if (i == sizes.size() / 2) row.push_back(soldierAt(soldier, 6.0f, kBehind));
        const float distance = distanceForSize(soldier, camera, sizes[i]);
        // Alternate sides so that near soldiers do not hide the far ones (the ranking does not care);
        // the tied pair stands in one place, so its sizes are equal to the last bit on any device.
        const bool tiedWithPrevious = i > 0 && sizes[i] == sizes[i - 1];
        const float angle = i % 2 == 0 ? 0.05f : -0.05f;
        const crowd::Character c = tiedWithPrevious ? previous : soldierAt(soldier, distance, angle);
        row.push_back(c);
        previous = c;
    }
    row.push_back(soldierAt(soldier, 9.0f, kBehind));
    return row;
}

struct Candidate {
    std::uint32_t character;
    float size;
};

// The characters in view and their sizes, as the CPU reference computes them from the GPU's records,
// ranked by the rule: larger first, ties by lower index.
std::vector<Candidate> rankedCandidates(const gpu::CullUniforms& cull, const std::vector<gpu::CharacterRecord>& records,
                                        const gpu::ModelRecord& model) {
    std::vector<Candidate> ranked;
    for (std::uint32_t c = 0; c < records.size(); ++c) {
        const glm::vec4 sphere = crowd::worldSphere(records[c], model);
        if (crowd::sphereInFrustum(cull.planes, sphere)) ranked.push_back({c, crowd::projectedDiameter(sphere, cull.camera)});
    }
    std::sort(ranked.begin(), ranked.end(), [](const Candidate& a, const Candidate& b) {
        return a.size != b.size ? a.size > b.size : a.character < b.character;
    });
    return ranked;
}

std::set<std::uint32_t> meshCharacters(const crowd::VisibleLists& lists) {
    std::set<std::uint32_t> mesh;
    for (const std::vector<std::uint32_t>& list : lists) mesh.insert(list.begin(), list.end());
    return mesh;
}

struct CutResult {
    crowd::VisibleLists gpuLists, cpuLists;
    std::vector<std::uint32_t> gpuImpostors, cpuImpostors;
    std::vector<Candidate> ranked;
    render::LodCounts counts;
};

// One frame of the row with this capacity: the GPU's lists, the CPU reference's from the same records,
// and the ranking. Shares the atlas of the first renderer (baked once).
CutResult cutRow(const gpu::VulkanContext& context, const model::SkinnedModel& soldier, std::uint32_t capacity,
                 std::shared_ptr<const render::ImpostorAtlas>& atlas) {
    const render::Camera camera = rowCamera(soldier);
    crowd::Crowd crowd(soldier, buildRow(soldier, camera));
    test::RendererOptions options;
    options.size = kImage;
    options.method = skin::Method::Compute;
    options.shadows = false;  // the view alone decides who qualifies
    options.cull.impostors = true;
    options.cull.impostorThreshold = 4.0f;  // every soldier in view qualifies for a mesh level
    options.meshCapacity = capacity;
    options.atlas = atlas;
    test::TestRenderer renderer(context, crowd, options);
    atlas = renderer.impostorAtlas();
    renderer.camera = test::appCamera(camera);
    renderer.renderFrame(0.0f);
    renderer.finish();
    CutResult result;
    result.counts = test::internalCounts(renderer.stats().back().lods);
    result.gpuLists = test::readVisibleLists(context, renderer);
    result.gpuImpostors = test::readImpostorList(context, renderer);
    const std::vector<gpu::CharacterRecord> records = test::readCharacterRecords(context, renderer);
    const gpu::CullUniforms cull = renderer.cullUniforms();
    std::vector<std::uint32_t> lodState(records.size(), 0u);
    result.cpuLists = crowd::cullOnCpu(cull, records, renderer.pool().models(), lodState, &result.cpuImpostors);
    std::sort(result.cpuImpostors.begin(), result.cpuImpostors.end());
    result.ranked = rankedCandidates(cull, records, renderer.pool().models()[0]);
    return result;
}

// Where the row's cluster starts in the ranking: two places above the tied pair (P, Q, T1, T2 are
// consecutive by size), or the ranking's end when no two sizes tie.
std::size_t clusterStart(const std::vector<Candidate>& ranked) {
    for (std::size_t i = 2; i + 1 < ranked.size(); ++i)
        if (ranked[i].size == ranked[i + 1].size) return i - 2;
    return ranked.size();
}

}  // namespace

TEST(FarthestFirst, KeepsTheLargestAndGivesExactTiesToTheLowerIndex) {
    // Characters 7, 3, 9, 4, 1, 8 at sizes 10, 40, 20, 20, 30, 20 px: ranked 3 (40), 1 (30), then the tie at
    // 20 px by index: 4, 8, 9, then 7 (10).
    const crowd::SizedCharacter candidates[] = {{7, 10.0f}, {3, 40.0f}, {9, 20.0f}, {4, 20.0f}, {1, 30.0f}, {8, 20.0f}};
    const auto kept = [&](std::uint32_t capacity) {
        std::set<std::uint32_t> characters;
        const std::vector<bool> keeps = crowd::keepsMesh(candidates, capacity);
        for (std::size_t i = 0; i < keeps.size(); ++i)
            if (keeps[i]) characters.insert(candidates[i].character);
        return characters;
    };
    EXPECT_EQ(kept(1), (std::set<std::uint32_t>{3}));
    EXPECT_EQ(kept(2), (std::set<std::uint32_t>{3, 1}));
    EXPECT_EQ(kept(3), (std::set<std::uint32_t>{3, 1, 4}));
    EXPECT_EQ(kept(4), (std::set<std::uint32_t>{3, 1, 4, 8}));
    EXPECT_EQ(kept(5), (std::set<std::uint32_t>{3, 1, 4, 8, 9}));
    EXPECT_EQ(kept(6), (std::set<std::uint32_t>{3, 1, 4, 8, 9, 7}));
    EXPECT_EQ(kept(60), kept(6)) << "no more candidates than the cap: all keep their meshes";
    // The camera inside a pose sphere makes it "infinitely" large (3e38): still a size like any other.
    const crowd::SizedCharacter inside[] = {{5, 3.0e38f}, {2, 3.0e38f}, {0, 1.0f}};
    EXPECT_EQ(crowd::keepsMesh(inside, 1), (std::vector<bool>{false, true, false}));
}

TEST_F(GpuTest, MeshCapacityDemotesTheSmallestOnScreenFirst) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    std::shared_ptr<const render::ImpostorAtlas> atlas;
    // The ranking does not depend on the capacity: take it from a first run that demotes nothing.
    const auto inView = static_cast<std::uint32_t>(buildRow(soldier, rowCamera(soldier)).size() - 2);
    const CutResult all = cutRow(*context, soldier, inView, atlas);
    const std::vector<Candidate>& ranked = all.ranked;
    const std::size_t p = clusterStart(ranked);
    ASSERT_LE(p + 4, ranked.size()) << "the cluster P, Q, T1, T2 is in view";
    // The premises: the cluster shares one coarse bucket; P > Q > T1 == T2 exactly; the rest lie elsewhere.
    for (std::size_t i = 0; i < ranked.size(); ++i) {
        const bool inCluster = i >= p && i < p + 4;
        EXPECT_EQ(coarseBucket(ranked[i].size) == coarseBucket(ranked[p].size), inCluster) << "rank " << i;
    }
    EXPECT_GT(ranked[p].size, ranked[p + 1].size);
    EXPECT_GT(ranked[p + 1].size, ranked[p + 2].size);
    EXPECT_EQ(ranked[p + 2].size, ranked[p + 3].size) << "T1 and T2 tie exactly";
    EXPECT_LT(ranked[p + 2].character, ranked[p + 3].character);
    ASSERT_EQ(ranked.size(), inView);
    EXPECT_EQ(all.counts.demoted, 0u) << "no more qualify than the capacity";
    EXPECT_EQ(meshCharacters(all.gpuLists).size(), ranked.size());

    // Capacities cutting between coarse buckets (3), inside the cluster's bucket (between Q and T1) and
    // through the tie (T1 kept, T2 demoted: the lower index wins).
    for (const std::size_t capacity : {std::size_t{3}, p + 2, p + 3}) {
        SCOPED_TRACE("capacity " + std::to_string(capacity));
        const CutResult cut = cutRow(*context, soldier, static_cast<std::uint32_t>(capacity), atlas);
        ASSERT_EQ(cut.ranked.size(), ranked.size());
        const std::set<std::uint32_t> gpuMesh = meshCharacters(cut.gpuLists);
        std::set<std::uint32_t> expectedMesh, expectedImpostors;
        for (std::size_t i = 0; i < ranked.size(); ++i)
            (i < capacity ? expectedMesh : expectedImpostors).insert(ranked[i].character);
        EXPECT_EQ(gpuMesh.size(), capacity) << "the mesh levels are filled exactly to the capacity";
        EXPECT_EQ(gpuMesh, expectedMesh) << "the largest on screen keep their meshes";
        EXPECT_EQ(std::set<std::uint32_t>(cut.gpuImpostors.begin(), cut.gpuImpostors.end()), expectedImpostors);
        EXPECT_EQ(cut.counts.demoted, ranked.size() - capacity);
        // No demoted character is larger on screen than a kept one.
        float smallestMesh = 1e30f, largestDemoted = 0.0f;
        for (const Candidate& c : ranked) {
            if (gpuMesh.count(c.character)) smallestMesh = std::min(smallestMesh, c.size);
            else largestDemoted = std::max(largestDemoted, c.size);
        }
        EXPECT_GE(smallestMesh, largestDemoted);
        // The GPU chose what the CPU reference chose, bucket by bucket.
        EXPECT_EQ(cut.gpuLists, cut.cpuLists);
        EXPECT_EQ(cut.gpuImpostors, cut.cpuImpostors);
    }
}

namespace {

struct GpuCandidate {
    std::uint32_t character;
    std::uint32_t sizeBits;
    bool drawnIfDemoted;
};

// The last frame's candidates of the cut, as the cull pass listed them (their sizes as the GPU computed them).
std::vector<GpuCandidate> readCandidates(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const render::DrawLists& lists = renderer.drawLists();
    gpu::ImpostorFrame frame;
    std::memcpy(&frame, test::readBuffer(context, lists.impostorFrame()).data(), sizeof frame);
    const std::vector<std::byte> bytes = test::readBuffer(context, lists.meshCandidates());
    std::vector<GpuCandidate> candidates;
    for (std::uint32_t i = 0; i < frame.meshCount; ++i) {
        glm::uvec2 entry;
        std::memcpy(&entry, bytes.data() + i * sizeof entry, sizeof entry);
        candidates.push_back({entry.x, entry.y & ~MESH_CUT_DRAWN_BIT, (entry.y & MESH_CUT_DRAWN_BIT) != 0});
    }
    return candidates;
}

}  // namespace

// Along a fly-over path (900 soldiers, shadows on, so casters outside the view are candidates too), the
// cut moves from frame to frame; each frame's meshes are exactly the rule's choice among the candidates
// the GPU listed, with the sizes it computed, and the demoted ones in view are drawn as impostors.
TEST_F(GpuTest, MeshCutFollowsTheRuleAlongACameraPath) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 900;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.cull.lodThresholds[0] = 30.0f;
    options.cull.lodThresholds[1] = 12.0f;
    options.cull.impostors = true;
    options.cull.impostorThreshold = 4.0f;
    options.meshCapacity = 90;
    test::TestRenderer renderer(*context, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    std::set<std::uint32_t> demotedCounts;
    std::uint32_t framesWithinCapacity = 0;
    std::size_t demotedInView = 0, demotedCasters = 0;
    for (float seconds : {0.0f, 3.0f, 6.0f, 9.0f, 12.0f, 15.0f, 18.0f, 20.0f}) {
        SCOPED_TRACE("at " + std::to_string(seconds) + " s");
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, shape, 160.0f / 90.0f, seconds);
        renderer.renderFrame(seconds);
        renderer.finish();
        const std::vector<GpuCandidate> candidates = readCandidates(*context, renderer);
        std::vector<crowd::SizedCharacter> sized;
        for (const GpuCandidate& c : candidates) sized.push_back({c.character, std::bit_cast<float>(c.sizeBits)});
        const std::vector<bool> keeps = crowd::keepsMesh(sized, options.meshCapacity);
        std::set<std::uint32_t> expectedMesh, drawnDemoted, hiddenDemoted;
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            if (keeps[i]) expectedMesh.insert(candidates[i].character);
            else (candidates[i].drawnIfDemoted ? drawnDemoted : hiddenDemoted).insert(candidates[i].character);
        }
        const std::set<std::uint32_t> gpuMesh = meshCharacters(test::readVisibleLists(*context, renderer));
        EXPECT_EQ(gpuMesh, expectedMesh);
        EXPECT_EQ(gpuMesh.size(), std::min<std::size_t>(candidates.size(), options.meshCapacity));
        const std::vector<std::uint32_t> impostors = test::readImpostorList(*context, renderer);
        for (std::uint32_t c : drawnDemoted) EXPECT_TRUE(std::binary_search(impostors.begin(), impostors.end(), c)) << c;
        for (std::uint32_t c : hiddenDemoted) EXPECT_FALSE(std::binary_search(impostors.begin(), impostors.end(), c)) << c;
        const render::LodCounts counts = test::internalCounts(renderer.takeStats().back().lods);
        EXPECT_EQ(counts.demoted, drawnDemoted.size() + hiddenDemoted.size());
        demotedCounts.insert(counts.demoted);
        framesWithinCapacity += counts.demoted == 0 ? 1u : 0u;
        demotedInView += drawnDemoted.size();
        demotedCasters += hiddenDemoted.size();
    }
    // Not a trivial path: the cut falls in a different place in different frames, some frames fit, and
    // the demoted include characters in view and casters outside it.
    EXPECT_GT(demotedCounts.size(), 3u);
    EXPECT_GT(framesWithinCapacity, 0u);
    EXPECT_GT(demotedInView, 0u);
    EXPECT_GT(demotedCasters, 0u);
}

// A crowd at every level with half its mesh-level characters demoted by the cap, against the same frame
// with no cap: near the camera, where the largest characters are, the pictures agree (99.5 % of the
// lower 40 % of the image within 2/255), while the demoted ones change the far field. Culling on the CPU
// with the cap draws the same picture as on the GPU.
TEST_F(GpuTest, NearCharactersKeepTheirMeshesUnderASmallMeshCapacity) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    app::SceneOptions scene;
    scene.count = 400;
    std::shared_ptr<const render::ImpostorAtlas> atlas;
    enum Run { Uncapped, Capped, CappedOnCpu };
    app::Rgba8Image images[3];
    render::LodCounts counts[3];
    std::uint32_t capacity = 0;  // none in the first run; then half of its meshes
    for (const Run run : {Uncapped, Capped, CappedOnCpu}) {
        crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
        test::RendererOptions options;
        options.size = {320, 180};
        options.method = skin::Method::Compute;
        options.cull.lodThresholds[0] = 22.0f;
        options.cull.lodThresholds[1] = 17.0f;
        options.cull.impostorThreshold = 14.0f;
        options.cull.hysteresis = 0.0f;
        options.cull.impostors = true;
        options.cull.mode = run == CappedOnCpu ? render::CullMode::Cpu : render::CullMode::Gpu;
        options.meshCapacity = capacity;
        options.atlas = atlas;
        test::TestRenderer renderer(*context, crowd, options);
        atlas = renderer.impostorAtlas();
        renderer.camera = app::cameraOnPath(app::CameraPath::Framed, test::shapeOf(crowd), 320.0f / 180.0f, 0.0f);
        renderer.renderFrame(11.0f);
        renderer.finish();
        counts[run] = test::internalCounts(renderer.takeStats().back().lods);
        images[run] = renderer.readback();
        capacity = counts[Uncapped].visible() / 2;
    }
    ASSERT_GT(capacity, 0u);
    EXPECT_EQ(counts[Uncapped].demoted, 0u);
    for (const Run run : {Capped, CappedOnCpu}) {
        EXPECT_EQ(counts[run].visible(), capacity) << "run " << run;
        EXPECT_EQ(counts[run].demoted, counts[Uncapped].visible() - capacity) << "run " << run;
    }
    const std::uint32_t w = images[0].width, h = images[0].height, nearRows = h * 2 / 5;
    app::Rgba8Image nearField[2];
    for (const Run run : {Uncapped, Capped}) {
        nearField[run] = {w, nearRows, {}};
        nearField[run].pixels.assign(images[run].pixels.end() - std::ptrdiff_t{w} * nearRows * 4, images[run].pixels.end());
    }
    const double near = test::fractionOfMatchingPixels(nearField[Uncapped], nearField[Capped], 2);
    const double whole = test::fractionOfMatchingPixels(images[Uncapped], images[Capped], 2);
    std::printf("capacity %u of %u meshes: near field %.2f %% matching, whole image %.2f %%\n", capacity,
                counts[Uncapped].visible(), 100.0 * near, 100.0 * whole);
    EXPECT_GE(near, 0.995);
    EXPECT_LT(whole, 0.999) << "the demoted characters are drawn as impostors";
    EXPECT_GE(test::fractionOfMatchingPixels(images[Capped], images[CappedOnCpu], 2), 0.999)
        << "CPU culling demotes the characters GPU culling demotes";
    if (near < 0.995 || std::getenv("CROWD_KEEP_IMAGES")) {
        app::writePng(test::artifactPath("capacity-uncapped.png"), images[Uncapped]);
        app::writePng(test::artifactPath("capacity-capped.png"), images[Capped]);
    }
}
