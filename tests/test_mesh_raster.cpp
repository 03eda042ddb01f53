// Small characters' meshes in the compute rasterizer (docs/compute-raster.md, "Meshes"): the picture of a
// crowd of meshes against the hardware path's, the visibility buffer's ids against a CPU projection of the
// skinned triangles, and a character moving between the paths from frame to frame.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#include "app/camera_path.h"
#include "app/crowd_renderer.h"
#include "render/frame_view.h"
#include "api/renderer_data.h"
#include "render/geometry_pool.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

struct MeshFrame {
    app::Rgba8Image image;
    render::LodCounts lods;
    std::vector<std::uint64_t> visibility;  // empty on the hardware path
    gpu::MeshSplit split{};
};

MeshFrame renderFrame(const gpu::VulkanContext& context, test::TestRenderer& renderer, double time) {
    renderer.renderFrame(time);
    renderer.finish();
    MeshFrame frame;
    frame.lods = test::internalCounts(renderer.takeStats().back().lods);
    frame.image = renderer.readback();
    const render::MeshRaster* raster = renderer.recorder().meshRaster();
    if (raster && renderer.recorder().meshesInComputeThisFrame(0)) {
        frame.visibility = test::readAll<std::uint64_t>(context, raster->visibility(0));
        frame.split = test::readAll<gpu::MeshSplit>(context, raster->split()).at(0);
    }
    return frame;
}

test::RendererOptions meshOptions(VkExtent2D size, render::RasterMode raster) {
    test::RendererOptions options;
    options.size = size;
    options.method = skin::Method::Compute;
    options.cull.impostors = false;
    options.cull.hysteresis = 0.0f;
    options.cull.lodFade = false;  // fading characters stay on the hardware path; here every one may go
    options.framesInFlight = 1;
    options.raster = raster;
    return options;
}


// The pose sphere in world space, as culling places it (shaders/cull.glsl.inc, worldSphere).
glm::vec4 worldSphere(const model::SkinnedModel& model, const crowd::Character& character) {
    const glm::vec3 local = glm::vec3(model.poseSphere) * character.scale;
    const float s = std::sin(character.heading), c = std::cos(character.heading);
    const glm::vec3 turned(c * local.x + s * local.z, local.y, c * local.z - s * local.x);
    return glm::vec4(character.position + turned, model.poseSphere.w * character.scale);
}

}  // namespace

// The mixed scene's crowd (soldiers and horses, 3:1, on its fly-over camera at 3 s), every character a
// mesh at its level, shadows on, drawn by the hardware and with --raster compute: every character the
// camera sees whole goes to compute (the split's count), and the pictures agree on 99.5 % of all
// pixels within 2/255 and, over the pixels compute covered, on 98 % within 2/255 and 99.5 % within
// 24/255 (the same coverage rule, the same shading; they differ by float rounding of the interpolation).
TEST_F(GpuTest, MeshRasterDrawsTheHardwarePictureOfAMixedCrowd) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    crowd::Crowd crowd = test::mixedCrowd(soldier, horse, 600);
    test::RendererOptions options = meshOptions({480, 270}, render::RasterMode::Hardware);
    test::TestRenderer hardware(*device, crowd, options);
    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, crowd, options);
    EXPECT_EQ(hardware.recorder().meshRaster(), nullptr);
    ASSERT_NE(compute.recorder().meshRaster(), nullptr);
    for (test::TestRenderer* r : {&hardware, &compute})
        r->camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 480.0f / 270.0f, 3.0);
    const MeshFrame h = renderFrame(*context, hardware, 11.0);
    const MeshFrame c = renderFrame(*context, compute, 11.0);
    const std::uint32_t meshes = c.lods.characters[0] + c.lods.characters[1] + c.lods.characters[2];
    EXPECT_GT(meshes, 40u);
    EXPECT_GT(c.split.computeCount, meshes / 2);  // those wholly in front of the eye
    EXPECT_LE(c.split.computeCount, meshes);
    std::size_t covered = 0, coveredClose = 0, coveredNear = 0, matching = 0;
    for (std::size_t i = 0; i < c.visibility.size(); ++i) {
        matching += test::pixelWithin(h.image, c.image, i, 2) ? 1 : 0;
        if (c.visibility[i] == kEmpty) continue;
        ++covered;
        coveredClose += test::pixelWithin(h.image, c.image, i, 2) ? 1 : 0;
        coveredNear += test::pixelWithin(h.image, c.image, i, 24) ? 1 : 0;
    }
    const double all = double(matching) / double(c.visibility.size());
    const double close = double(coveredClose) / double(std::max<std::size_t>(covered, 1));
    const double near = double(coveredNear) / double(std::max<std::size_t>(covered, 1));
    std::printf("%u of %u meshes in compute cover %zu pixels; within 2/255: %.2f %% of all pixels, %.2f %% of the "
                "covered ones; within 24/255: %.2f %% of the covered ones\n", c.split.computeCount, meshes, covered,
                100.0 * all, 100.0 * close, 100.0 * near);
    EXPECT_GT(covered, 2000u);
    EXPECT_GE(all, 0.995);
    EXPECT_GE(close, 0.98);
    EXPECT_GE(near, 0.995);
    if (HasFailure() || std::getenv("CROWD_KEEP_IMAGES")) test::keepRasterImages("mesh-raster-mixed", h.image, c.image);
}

// Ids: five soldiers far apart at different distances, every one in compute. Every covered pixel's id
// names, through the list and the colour command, a character and a triangle; that triangle, projected
// on the CPU from the skinned vertices the GPU read (the camera's matrices), is front-facing and holds
// the pixel centre (to 1/64 px: the rasterizer snaps corners to 1/256 px), and the character is the one
// whose pose sphere's projection holds the pixel. Every soldier covers pixels.
TEST_F(GpuTest, MeshVisibilityIdsDecodeToTheCharacterAndTriangle) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    std::vector<crowd::Character> characters(5);
    // The rifle only: the pose sphere holds the props at least half the crowd carries, not a flag.
    std::uint32_t rifle = 0;
    for (std::size_t k = 0; k < soldier.props.size(); ++k)
        if (soldier.props[k].name == "rifle") rifle |= 1u << k;
    for (int i = 0; i < 5; ++i) {
        characters[i].props = rifle;
        characters[i].position = glm::vec3(-4.0f + 2.0f * float(i), 0.0f, -3.0f * float(i));
        characters[i].heading = 0.7f * float(i);
        characters[i].timeOffset = 0.2f * float(i);
    }
    crowd::Crowd crowd(soldier, characters);
    test::RendererOptions options = meshOptions({240, 160}, render::RasterMode::Compute);
    options.shadows = false;
    test::TestRenderer renderer(*device, crowd, options);
    render::Camera camera;
    camera.eye = glm::vec3(0.0f, 2.0f, 9.0f);
    camera.target = glm::vec3(0.0f, 0.9f, -4.0f);
    renderer.camera = test::appCamera(camera);
    const MeshFrame frame = renderFrame(*context, renderer, 1.3);
    ASSERT_EQ(frame.split.computeCount, 5u);
    const render::MeshRaster& raster = *renderer.recorder().meshRaster();
    const std::vector<std::uint32_t> listed = test::readAll<std::uint32_t>(*context, raster.list());
    const std::vector<gpu::DrawIndexedCommand> draws = test::readAll<gpu::DrawIndexedCommand>(*context, renderer.drawLists().draws());
    // The pool's indices, from the model's levels (one model: its levels lie at the record's first indices).
    const gpu::ModelRecord record = renderer.pool().models().at(0);
    const std::vector<model::SkinnedModel::Lod> lods = render::lodsOf(soldier);
    auto indexAt = [&](std::uint32_t pooled) {
        for (int l = LOD_COUNT - 1; l >= 0; --l)
            if (pooled >= record.lodFirstIndex[l]) return lods.at(l).indices.at(pooled - record.lodFirstIndex[l]);
        ADD_FAILURE() << "index " << pooled << " before the model's";
        return 0u;
    };
    std::uint32_t vertexCount = 0;
    for (std::uint32_t place = 0; place < 5; ++place)
        vertexCount = std::max(vertexCount, std::uint32_t(draws.at(listed.at(place)).vertexOffset) + soldier.lods.at(0).vertexCount);
    const std::vector<glm::vec4> positions =
        test::readSkinnedVertices(*context, renderer.method().skinnedVertices(), 0, vertexCount).positions;
    const render::FrameView view = render::frameViewOf(camera, {240, 160}, 1.3);
    const glm::mat4 viewProjection = view.projection * view.view;
    const glm::vec2 extent(240.0f, 160.0f);
    auto toScreen = [&](glm::vec3 p) {
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        return glm::vec3((glm::vec2(clip) / clip.w * 0.5f + 0.5f) * extent, clip.w);
    };
    std::vector<std::size_t> pixelsOf(5, 0);
    std::size_t covered = 0, wrong = 0;
    for (std::size_t i = 0; i < frame.visibility.size(); ++i) {
        if (frame.visibility[i] == kEmpty) continue;
        ++covered;
        const std::uint32_t id = std::uint32_t(frame.visibility[i]) & ~MESH_RASTER_ID_BIT;
        const std::uint32_t place = id >> raster.triangleBits(), triangle = id & ((1u << raster.triangleBits()) - 1u);
        ASSERT_LT(place, 5u);
        const gpu::DrawIndexedCommand& command = draws.at(listed.at(place));
        ASSERT_LT(triangle, command.indexCount / 3);
        glm::vec3 s[3];
        for (int k = 0; k < 3; ++k)
            s[k] = toScreen(glm::vec3(positions.at(std::size_t(int(indexAt(command.firstIndex + 3 * triangle + k)) +
                                                           command.vertexOffset))));
        const glm::vec2 centre(float(i % 240) + 0.5f, float(i / 240) + 0.5f);
        auto edge = [](glm::vec2 a, glm::vec2 b, glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
        const float area = edge(glm::vec2(s[0]), glm::vec2(s[1]), glm::vec2(s[2]));
        const float slack = 1.0f / 64.0f * glm::length(glm::vec2(s[1] - s[0]) + glm::vec2(s[2] - s[0])) + 1e-3f;
        // Front-facing is a negative area here (Vulkan's counter-clockwise with y down); inside, every
        // edge function has the area's sign.
        const bool front = area < 0.0f;
        const bool inside = edge(glm::vec2(s[1]), glm::vec2(s[2]), centre) <= slack &&
                            edge(glm::vec2(s[2]), glm::vec2(s[0]), centre) <= slack &&
                            edge(glm::vec2(s[0]), glm::vec2(s[1]), centre) <= slack;
        const std::uint32_t character = command.firstInstance;
        const glm::vec4 sphere = worldSphere(soldier, characters.at(character));
        const glm::vec3 c = toScreen(glm::vec3(sphere));
        const float radius = sphere.w * std::abs(view.projection[1][1]) * 0.5f * extent.y / c.z * 1.05f;
        const bool inSphere = glm::length(glm::vec2(c) - centre) <= radius + 1.0f;
        if (!front || !inside || !inSphere) ++wrong;
        ++pixelsOf.at(character);
    }
    std::printf("%zu covered pixels, per soldier:", covered);
    for (std::size_t n : pixelsOf) std::printf(" %zu", n);
    std::printf("; %zu wrong\n", wrong);
    EXPECT_EQ(wrong, 0u);
    for (std::size_t n : pixelsOf) EXPECT_GT(n, 20u);
}

// A soldier walking towards the camera crosses auto's mesh limit (40 px here): drawn in compute while
// smaller, by the hardware once larger (the split's count says which). In every frame its pixels equal the
// hardware-only renderer's within 2/255 on 98 % and within 24/255 on 99.5 %.
TEST_F(GpuTest, AMeshCrossingAutosLimitKeepsItsPixels) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Character one;
    one.heading = 0.4f;
    crowd::Crowd crowd(soldier, {one});
    crowd::Character gone = one;
    gone.scale = 1e-3f;
    crowd::Crowd empty(soldier, {gone});
    test::RendererOptions options = meshOptions({160, 120}, render::RasterMode::Hardware);
    options.shadows = false;
    test::TestRenderer hardware(*device, crowd, options);
    test::TestRenderer emptyRenderer(*device, empty, options);
    options.raster = render::RasterMode::Auto;
    options.meshRasterLimitPixels = 40.0f;
    test::TestRenderer automatic(*device, crowd, options);
    std::uint32_t onCompute = 0, onHardware = 0;
    for (int step = 0; step < 8; ++step) {
        const float across = 32.0f + 2.0f * float(step);
        const render::Camera camera = test::cameraSeeingSphereAcross(soldier, across);
        for (test::TestRenderer* r : {&hardware, &automatic, &emptyRenderer}) r->camera = test::appCamera(camera);
        const MeshFrame h = renderFrame(*context, hardware, 0.25 * step);
        const MeshFrame a = renderFrame(*context, automatic, 0.25 * step);
        const MeshFrame e = renderFrame(*context, emptyRenderer, 0.25 * step);
        ASSERT_LE(a.split.computeCount, 1u);
        onCompute += a.split.computeCount;
        onHardware += 1 - a.split.computeCount;
        const test::CharacterAgreement agreement = test::characterAgreement(h.image, a.image, e.image);
        std::printf("%.0f px: %s path, %zu soldier pixels, %.1f %% within 2/255, %.1f %% within 24/255\n", across,
                    a.split.computeCount ? "compute" : "hardware", agreement.pixels, 100.0 * agreement.share2(),
                    100.0 * agreement.share24());
        EXPECT_GT(agreement.pixels, 100u);
        EXPECT_GE(agreement.share2(), 0.98) << "step " << step;
        EXPECT_GE(agreement.share24(), 0.995) << "step " << step;
        if (HasFailure()) test::keepRasterImages("mesh-raster-switch", h.image, a.image);
    }
    EXPECT_GE(onCompute, 2u);
    EXPECT_GE(onHardware, 2u);
}

// The top-left rule: the glTF strip (1 x 2 m, four triangles: two quads cut by their diagonals), facing
// the camera, 8 px to the metre, its six corners on pixel centres, so its outer edges and both diagonals
// run through pixel centres. Drawn by the hardware and in compute: the same pixels are covered (the
// outer edges: left and top kept, right and bottom not), and every pixel's triangle in the visibility
// buffer holds its centre by the rule, computed on the CPU from the snapped corners (an edge function
// above 0, or 0 on a top or left edge) — so a centre on a diagonal belongs to the one triangle whose
// top or left edge it is.
TEST_F(GpuTest, MeshRasterFollowsTheTopLeftRule) {
    const model::SkinnedModel strip = test::loadText(test::stripCharacter().gltf());
    crowd::Character one;
    one.heading = 0.0f;  // its front (counter-clockwise) side towards the camera (+z)
    crowd::Crowd crowd(strip, {one});
    crowd::Character gone = one;
    gone.scale = 1e-3f;
    crowd::Crowd empty(strip, {gone});
    test::RendererOptions options = meshOptions({64, 64}, render::RasterMode::Hardware);
    options.shadows = false;
    options.cull.lod = false;  // the full mesh
    test::TestRenderer hardware(*device, crowd, options);
    test::TestRenderer emptyRenderer(*device, empty, options);
    options.raster = render::RasterMode::Compute;
    test::TestRenderer compute(*device, crowd, options);
    render::Camera camera;
    const float focal = 32.0f / std::tan(0.5f * camera.verticalFov);
    // Half a pixel (1/16 m) off the axis both ways: the screen's centre is a pixel corner.
    camera.eye = glm::vec3(-1.0f / 16.0f, 1.0f + 1.0f / 16.0f, focal / 8.0f);
    camera.target = camera.eye - glm::vec3(0.0f, 0.0f, 1.0f);
    camera.nearPlane = 0.5f;
    camera.farPlane = 100.0f;
    for (test::TestRenderer* r : {&hardware, &emptyRenderer, &compute}) r->camera = test::appCamera(camera);
    const MeshFrame h = renderFrame(*context, hardware, 0.0);
    const MeshFrame e = renderFrame(*context, emptyRenderer, 0.0);
    const MeshFrame c = renderFrame(*context, compute, 0.0);
    ASSERT_EQ(c.split.computeCount, 1u);
    const render::MeshRaster& raster = *compute.recorder().meshRaster();
    const std::vector<std::uint32_t> listed = test::readAll<std::uint32_t>(*context, raster.list());
    const gpu::DrawIndexedCommand command = test::readAll<gpu::DrawIndexedCommand>(*context, compute.drawLists().draws()).at(listed.at(0));
    const gpu::ModelRecord record = compute.pool().models().at(0);
    const std::vector<model::SkinnedModel::Lod> lods = render::lodsOf(strip);
    ASSERT_EQ(command.firstIndex, record.lodFirstIndex[0]);
    const std::vector<glm::vec4> positions =
        test::readSkinnedVertices(*context, compute.method().skinnedVertices(), std::uint32_t(command.vertexOffset),
                                  std::uint32_t(strip.vertices.size())).positions;
    const render::FrameView view = render::frameViewOf(camera, {64, 64}, 0.0);
    auto snapped = [&](glm::vec3 p) {
        const glm::vec4 clip = view.projection * view.view * glm::vec4(p, 1.0f);
        return glm::round((glm::vec2(clip) / clip.w * 0.5f + 0.5f) * 64.0f * 256.0f) / 256.0f;
    };
    auto topLeft = [](glm::vec2 a, glm::vec2 b) { return (a.y == b.y && b.x > a.x) || b.y < a.y; };
    auto edge = [](glm::vec2 a, glm::vec2 b, glm::vec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
    std::size_t hardwarePixels = 0, computePixels = 0, same = 0, onEdges = 0, byRule = 0;
    for (std::size_t i = 0; i < c.visibility.size(); ++i) {
        const bool hw = !test::pixelWithin(h.image, e.image, i, 0), cs = c.visibility[i] != kEmpty;
        hardwarePixels += hw, computePixels += cs, same += hw == cs;
        if (!cs) continue;
        const std::uint32_t triangle = (std::uint32_t(c.visibility[i]) & ~MESH_RASTER_ID_BIT) & ((1u << raster.triangleBits()) - 1u);
        glm::vec2 q[3];
        for (int k = 0; k < 3; ++k) q[k] = snapped(glm::vec3(positions.at(lods[0].indices.at(3 * triangle + k))));
        // Counter-clockwise on screen (negative area, y down) is the front: swap to make the inside positive.
        if (edge(q[0], q[1], q[2]) < 0.0f) std::swap(q[1], q[2]);
        const glm::vec2 centre(float(i % 64) + 0.5f, float(i / 64) + 0.5f);
        bool ok = true, onEdge = false;
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 a = q[(k + 1) % 3], b = q[(k + 2) % 3];
            const float w = edge(a, b, centre);
            onEdge = onEdge || w == 0.0f;
            ok = ok && (w > 0.0f || (w == 0.0f && topLeft(a, b)));
        }
        onEdges += onEdge, byRule += ok;
    }
    std::printf("strip: %zu pixels on the hardware, %zu in compute, %zu agree of 4096; %zu centres on an edge, %zu of "
                "%zu by the rule\n", hardwarePixels, computePixels, same, onEdges, byRule, computePixels);
    EXPECT_EQ(hardwarePixels, 8u * 16u);  // 8 x 16 px: left and top edges in, right and bottom out
    EXPECT_EQ(same, c.visibility.size());
    EXPECT_GT(onEdges, 16u);  // both diagonals and the outer left and top edges
    EXPECT_EQ(byRule, computePixels);
    if (HasFailure()) test::keepRasterImages("mesh-raster-top-left", h.image, c.image);
}

// The library refuses a mesh limit that is negative (but -1, automatic) or not a number, in one line.
TEST_F(GpuTest, MeshRasterLimitIsChecked) {
    for (const float bad : {-2.0f, -0.5f, std::nanf(""), 2e6f}) {
        crowdgpu::RendererSettings settings;
        settings.meshRasterLimit = bad;
        try {
            (void)crowdgpu::detail::rendererOptions(settings);
            ADD_FAILURE() << "mesh raster limit " << bad << " accepted";
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(e.what()).find("mesh raster limit"), std::string::npos) << e.what();
        }
    }
}

// Auto's automatic limit engages the mesh path on a frame whose slot's previous frame drew at least the
// threshold's mesh triangles, and not otherwise: the mixed crowd's fly-over, one frame in flight. With the
// threshold under what the crowd draws, the first frame (no history) stays on the hardware and the next
// goes to compute with the hardware's picture (99.5 % of pixels within 2/255); with the threshold above
// it, no frame does, and the pictures are the hardware's exactly.
TEST_F(GpuTest, AutoEngagesTheMeshPathAfterAFrameOfManyTriangles) {
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const model::SkinnedModel horse = test::loadModel("horse", 1);
    crowd::Crowd crowd = test::mixedCrowd(soldier, horse, 600);
    test::RendererOptions options = meshOptions({480, 270}, render::RasterMode::Hardware);
    test::TestRenderer hardware(*device, crowd, options);
    options.raster = render::RasterMode::Auto;
    ASSERT_EQ(options.meshRasterLimitPixels, render::kMeshRasterAutomatic);  // the default
    options.meshRasterMinTriangles = 10'000;
    test::TestRenderer engaged(*device, crowd, options);
    options.meshRasterMinTriangles = 100'000'000;
    test::TestRenderer idle(*device, crowd, options);
    for (test::TestRenderer* r : {&hardware, &engaged, &idle})
        r->camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 480.0f / 270.0f, 3.0);
    for (int frame = 0; frame < 3; ++frame) {
        const double time = 11.0 + frame / 60.0;
        const MeshFrame h = renderFrame(*context, hardware, time);
        const MeshFrame e = renderFrame(*context, engaged, time);
        const MeshFrame i = renderFrame(*context, idle, time);
        const std::uint64_t triangles = h.lods.triangles[0] + h.lods.triangles[1] + h.lods.triangles[2];
        ASSERT_GT(triangles, 10'000u);
        EXPECT_EQ(engaged.recorder().meshesInComputeThisFrame(0), frame > 0) << "frame " << frame;
        EXPECT_FALSE(idle.recorder().meshesInComputeThisFrame(0)) << "frame " << frame;
        if (frame > 0) {
            EXPECT_GT(e.split.computeCount, 20u) << "frame " << frame;
        }
        std::size_t close = 0, same = 0;
        for (std::size_t p = 0; p < h.image.pixels.size() / 4; ++p) {
            close += test::pixelWithin(h.image, e.image, p, 2) ? 1 : 0;
            same += test::pixelWithin(h.image, i.image, p, 0) ? 1 : 0;
        }
        EXPECT_GE(double(close) / double(h.image.pixels.size() / 4), 0.995) << "frame " << frame;
        EXPECT_EQ(same, h.image.pixels.size() / 4) << "frame " << frame;
    }
}
