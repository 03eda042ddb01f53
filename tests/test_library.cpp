// The library's front door as a host uses it: crowdgpu::Renderer on a device the test creates,
// recording into the test's own command buffers and its own target in another colour format.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include "crowdgpu/renderer.hpp"
#include "crowdgpu/version.h"
#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/image.h"
#include "gpu/one_shot_commands.h"
#include "gpu/vulkan_error.h"
#include "app/camera_path.h"
#include "app/render_target.h"
#include "render/scene_pass.h"
#include "support/gpu_test.h"
#include "support/host_frames.h"
#include "support/run_program.h"

// README.md's Embedding block, wrapped by tests/readme_embedding.cpp.in.
namespace readme {
void embeddingExample(const crowdgpu::Device& device, const std::function<void(VkCommandBuffer)>& submitAndWait,
                      VkCommandBuffer setupCmd, VkCommandBuffer cmd, std::uint32_t slot, const crowdgpu::FrameView& view,
                      double time, const VkRenderingInfo& yourColourPass,
                      const std::function<void(crowdgpu::Renderer&)>& frameRecorded);
}  // namespace readme

namespace {

using test::GpuTest;

// The host's device as the library sees it (tests/support/host_frames.h).
using HostDevice = test::LentDevice;

// The default scene's crowd of `count` soldiers, as crowd-render builds it.
crowdgpu::Crowd defaultCrowd(std::uint32_t count) {
    crowdgpu::GridLayout layout;
    layout.count = count;
    return crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
}

// crowd-render's camera for the default scene at `time`, as the host's matrices.
crowdgpu::FrameView defaultView(const crowdgpu::Crowd& crowd, VkExtent2D size, double time) {
    float center[3], radius, tallest;
    crowd.bounds(center, radius, tallest);
    const app::CrowdShape shape{glm::vec3(center[0], center[1], center[2]), radius, tallest};
    const float aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
    const app::Camera camera = app::cameraOnPath(app::CameraPath::Framed, shape, aspect, time);
    const float eye[3] = {camera.eye.x, camera.eye.y, camera.eye.z};
    const float target[3] = {camera.target.x, camera.target.y, camera.target.z};
    return crowdgpu::lookAt(eye, target, camera.verticalFov, camera.nearPlane, camera.farPlane, size, time);
}

// One frame the way a host draws it: the crowd planned, compute and shadows recorded, then the
// host's own colour pass with the ground and the characters.
void recordFrame(crowdgpu::Renderer& renderer, const crowdgpu::Crowd& crowd, VkCommandBuffer cmd, std::uint32_t slot,
                 const crowdgpu::FrameView& view, app::RenderTarget& target) {
    renderer.recordCompute(cmd, slot, view, crowd);
    renderer.recordShadows(cmd, slot);
    const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
    target.beginRendering(cmd, sky);
    renderer.recordGround(cmd, slot);
    renderer.recordCharacters(cmd, slot);
    target.endRendering(cmd);
}

void runSetup(const gpu::VulkanContext& context, crowdgpu::Renderer& renderer) {
    gpu::runOneShotNow(context, [&](VkCommandBuffer cmd) { renderer.recordSetup(cmd); });
    renderer.setupCompleted();
}

app::Rgba8Image bgraToRgba(app::Rgba8Image image) {
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) std::swap(image.pixels[i], image.pixels[i + 2]);
    return image;
}

app::Rgba8Image readPng(const std::string& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) return {};
    app::Rgba8Image image{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height),
                             std::vector<std::uint8_t>(data, data + std::size_t(width) * height * 4)};
    stbi_image_free(data);
    return image;
}

// A B8G8R8A8 colour image in TRANSFER_SRC_OPTIMAL, copied to the host as RGBA.
app::Rgba8Image readBgraImage(const gpu::VulkanContext& context, const gpu::Image& image) {
    const VkDeviceSize bytes = VkDeviceSize(image.extent.width) * image.extent.height * 4;
    gpu::Buffer staging = gpu::createBuffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            gpu::MemoryUse::HostReadback, "test readback");
    gpu::runOneShotNow(context, [&](VkCommandBuffer cmd) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {image.extent.width, image.extent.height, 1};
        vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &region);
    });
    const auto* data = static_cast<const std::uint8_t*>(staging.mapped);
    app::Rgba8Image result{image.extent.width, image.extent.height, std::vector<std::uint8_t>(data, data + bytes)};
    gpu::destroyBuffer(context, staging);
    return bgraToRgba(std::move(result));
}

const char* methodFlag(crowdgpu::Method method) {
    switch (method) {
        case crowdgpu::Method::TwoPass: return "two-pass";
        case crowdgpu::Method::VertexShader: return "vs";
        case crowdgpu::Method::Compute: return "compute";
        default: return "";
    }
}

}  // namespace

TEST(Library, VersionMacroAndFunctionAgree) {
    EXPECT_EQ(crowdgpu_version(), static_cast<unsigned>(CROWDGPU_VERSION));
    EXPECT_STREQ(crowdgpu_version_string(), "1.0.0");
}

// The embedded crowd in the host's B8G8R8A8_SRGB target is crowd-render's picture of the same crowd,
// camera and time, once the channels are swapped back; single-sampled, and with two-pass also with 4
// samples per pixel resolved (crowd-render --aa msaa4, the target's sample count in the settings).
TEST_F(GpuTest, EmbeddedCrowdEqualsCrowdRenderForTwoPassVsAndCompute) {
    const VkExtent2D size{256, 144};
    const std::pair<crowdgpu::Method, VkSampleCountFlagBits> runs[] = {
        {crowdgpu::Method::TwoPass, VK_SAMPLE_COUNT_1_BIT},
        {crowdgpu::Method::VertexShader, VK_SAMPLE_COUNT_1_BIT},
        {crowdgpu::Method::Compute, VK_SAMPLE_COUNT_1_BIT},
        {crowdgpu::Method::TwoPass, VK_SAMPLE_COUNT_4_BIT}};
    for (const auto& [method, samples] : runs) {
        const std::string png = test::artifactPath(std::string("library-crowd-render-") + methodFlag(method) + ".png");
        const test::ProgramResult r = test::runProgram(
            CROWD_RENDER_BINARY, std::string("--count 64 --method ") + methodFlag(method) + " --aa " +
                                     app::antiAliasingName(samples) + " --frames 1 --size 256x144 --validation --out " + png);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const app::Rgba8Image program = readPng(png);
        ASSERT_EQ(program.width, size.width);

        crowdgpu::Crowd crowd = defaultCrowd(64);
        HostDevice host(*context);
        crowdgpu::RendererSettings settings;
        settings.target = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_D32_SFLOAT, samples};
        settings.method = method;
        crowdgpu::Renderer renderer(host.device, crowd, settings);
        runSetup(*context, renderer);
        app::RenderTarget target(*device, size, settings.target);
        crowd.advanceTo(0.0f);
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            recordFrame(renderer, crowd, cmd, 0, defaultView(crowd, size, 0.0f), target);
        });
        const app::Rgba8Image embedded = bgraToRgba(target.readback());
        EXPECT_GE(test::fractionOfMatchingPixels(embedded, program, 1), 0.999)
            << methodFlag(method) << " " << app::antiAliasingName(samples);
        std::filesystem::remove(png);
    }
}

// RendererSettings::ground draws the checkered ground inside recordCharacters, after the opaque
// characters and before the far crowd's blended layer, so that the depth test rejects it under them
// before it is shaded. The picture must be recordGround's before recordCharacters, pixel for pixel, in a
// frame that has every kind of layer: meshes at two levels with fades, impostors through both
// rasterizers, the far crowd's layer; with one sample and four. The frame without any ground differs
// (the ground is drawn), and with the setting on recordGround is refused.
TEST_F(GpuTest, GroundBehindTheCharactersDrawsRecordGroundsPicture) {
    const VkExtent2D size{320, 180};
    crowdgpu::GridLayout layout;
    layout.count = 3000;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
    float center[3], radius, tallest;
    crowd.bounds(center, radius, tallest);
    // Four metres up just off the square's near edge (the bounding circle's radius over the square's
    // half side is sqrt 2), looking at its middle: soldiers at LOD 1 below to ones a pixel tall, the
    // ground between them.
    const float edge = center[2] + radius / std::sqrt(2.0f);
    const float eye[3] = {center[0], 4.0f, edge + 1.5f};
    const float at[3] = {center[0], 0.0f, center[2]};
    const double time = 1.0;
    crowd.advanceTo(time);
    const crowdgpu::FrameView view = crowdgpu::lookAt(eye, at, 0.8f, 0.1f, 400.0f, size, time);
    HostDevice host(*context);
    // The compute rasterizer's 64-bit atomics, optional features a host enables when it wants them.
    host.features.features.shaderInt64 = host.vulkan12.shaderBufferInt64Atomics = context->int64Atomics;
    for (const VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_4_BIT}) {
        crowdgpu::RendererSettings settings;
        settings.target = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_D32_SFLOAT, samples};
        settings.method = crowdgpu::Method::Compute;
        settings.impostors = true;
        settings.meshRasterLimit = 24.0f;  // the small meshes through the compute rasterizer's resolve too
        crowdgpu::Renderer renderer(host.device, crowd, settings);
        runSetup(*context, renderer);
        app::RenderTarget target(*device, size, settings.target);
        enum class Ground { Before, Behind, None };
        auto frame = [&](Ground ground) {
            renderer.setGround(ground == Ground::Behind);
            gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
                renderer.recordCompute(cmd, 0, view, crowd);
                renderer.recordShadows(cmd, 0);
                const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
                target.beginRendering(cmd, sky);
                if (ground == Ground::Before) renderer.recordGround(cmd, 0);
                renderer.recordCharacters(cmd, 0);
                target.endRendering(cmd);
            });
            return target.readback();
        };
        const app::Rgba8Image before = frame(Ground::Before);
        const crowdgpu::FrameCounts counts = renderer.counts(0);
        const app::Rgba8Image behind = frame(Ground::Behind);
        const app::Rgba8Image none = frame(Ground::None);
        const std::string label = samples == VK_SAMPLE_COUNT_1_BIT ? "one sample" : "four samples";
        // Every layer is in the frame (on lavapipe the impostors go through the compute rasterizer
        // with one sample and the hardware one with four).
        EXPECT_GT(counts.characters[1], 0u) << label;
        EXPECT_GT(counts.characters[2], 0u) << label;
        EXPECT_GT(counts.impostors, 500u) << label;
        std::printf("ground behind the characters, %s: LOD %u/%u/%u, %u impostors; pixels equal to recordGround's "
                    "%.4f, to no ground %.3f\n",
                    label.c_str(), counts.characters[0], counts.characters[1], counts.characters[2], counts.impostors,
                    test::fractionOfMatchingPixels(behind, before, 0), test::fractionOfMatchingPixels(none, before, 0));
        EXPECT_EQ(test::fractionOfMatchingPixels(behind, before, 0), 1.0) << label;
        EXPECT_LT(test::fractionOfMatchingPixels(none, before, 0), 0.92) << label << ": the ground is drawn";
        renderer.setGround(true);
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            renderer.recordCompute(cmd, 0, view, crowd);
            try {
                renderer.recordGround(cmd, 0);
                ADD_FAILURE() << "recordGround with the ground setting on: no error";
            } catch (const crowdgpu::Error& error) {
                EXPECT_EQ(error.code(), crowdgpu::ErrorCode::WrongOrder) << error.what();
                EXPECT_NE(std::string(error.what()).find("recordCharacters"), std::string::npos) << error.what();
            }
        });
    }
}

// Two renderers with two crowds in one host pass, two frames in flight, waiting only on each slot's
// own fence: validation silent, and the last frame equals each crowd drawn alone where it stands.
TEST_F(GpuTest, TwoRenderersShareOneHostFrameWithTwoFramesInFlight) {
    const VkExtent2D size{256, 144};
    crowdgpu::GridLayout layout;
    layout.count = 16;
    crowdgpu::Crowd soldiers = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
    std::vector<crowdgpu::Character> horses(4);
    for (std::uint32_t i = 0; i < horses.size(); ++i) horses[i].position[0] = 8.0f + 3.0f * static_cast<float>(i);
    crowdgpu::Crowd herd({crowdgpu::Model::horse(1)}, horses);
    HostDevice host(*context);
    crowdgpu::RendererSettings settings;
    settings.shadows = false;  // each renderer's ground would see only its own shadow map
    settings.method = crowdgpu::Method::Compute;
    crowdgpu::Renderer a(host.device, soldiers, settings), b(host.device, herd, settings);
    runSetup(*context, a);
    runSetup(*context, b);
    app::RenderTarget target(*device, size);
    const float eye[3] = {4.0f, 9.0f, 24.0f}, at[3] = {4.0f, 0.5f, 0.0f};

    std::vector<VkCommandBuffer> cmds(2);
    std::vector<VkFence> fences(2);
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context->commandPool;
    allocate.commandBufferCount = 2;
    ASSERT_EQ(vkAllocateCommandBuffers(context->device, &allocate, cmds.data()), VK_SUCCESS);
    for (VkFence& fence : fences) {
        VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        ASSERT_EQ(vkCreateFence(context->device, &info, nullptr, &fence), VK_SUCCESS);
    }
    const float lastTime = 5.0f / 60.0f;
    for (std::uint32_t frame = 0; frame < 6; ++frame) {
        const std::uint32_t slot = frame % 2;
        const double time = static_cast<double>(frame) / 60.0;
        ASSERT_EQ(vkWaitForFences(context->device, 1, &fences[slot], VK_TRUE, UINT64_MAX), VK_SUCCESS);
        vkResetFences(context->device, 1, &fences[slot]);
        soldiers.advanceTo(time);
        herd.advanceTo(time);
        const crowdgpu::FrameView view = crowdgpu::lookAt(eye, at, 0.8f, 0.1f, 200.0f, size, time);
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        vkBeginCommandBuffer(cmds[slot], &begin);
        a.recordCompute(cmds[slot], slot, view, soldiers);
        b.recordCompute(cmds[slot], slot, view, herd);
        a.recordShadows(cmds[slot], slot);
        b.recordShadows(cmds[slot], slot);
        const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
        target.beginRendering(cmds[slot], sky);
        a.recordGround(cmds[slot], slot);
        a.recordCharacters(cmds[slot], slot);
        b.recordCharacters(cmds[slot], slot);
        target.endRendering(cmds[slot]);
        vkEndCommandBuffer(cmds[slot]);
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmds[slot];
        ASSERT_EQ(vkQueueSubmit(context->queue, 1, &submit, fences[slot]), VK_SUCCESS);
    }
    vkWaitForFences(context->device, 2, fences.data(), VK_TRUE, UINT64_MAX);
    const app::Rgba8Image both = target.readback();
    EXPECT_GT(a.counts(1).characters[0] + a.counts(1).characters[1] + a.counts(1).characters[2], 0u);
    EXPECT_GT(b.counts(1).characters[0] + b.counts(1).characters[1] + b.counts(1).characters[2], 0u);

    // Each crowd alone at the same time: where it differs from the bare ground, the pair's frame is it.
    auto alone = [&](crowdgpu::Renderer* first, crowdgpu::Renderer* second) {
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            const crowdgpu::FrameView view = crowdgpu::lookAt(eye, at, 0.8f, 0.1f, 200.0f, size, lastTime);
            a.recordCompute(cmd, 0, view, soldiers);
            b.recordCompute(cmd, 0, view, herd);
            a.recordShadows(cmd, 0);
            b.recordShadows(cmd, 0);
            const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
            target.beginRendering(cmd, sky);
            a.recordGround(cmd, 0);
            if (first) first->recordCharacters(cmd, 0);
            if (second) second->recordCharacters(cmd, 0);
            target.endRendering(cmd);
        });
        return target.readback();
    };
    const app::Rgba8Image onlyA = alone(&a, nullptr), onlyB = alone(&b, nullptr), ground = alone(nullptr, nullptr);
    std::size_t pixelsA = 0, pixelsB = 0, matching = 0, covered = 0;
    for (std::size_t i = 0; i < both.pixels.size(); i += 4) {
        const bool inA = std::memcmp(&onlyA.pixels[i], &ground.pixels[i], 3) != 0;
        const bool inB = std::memcmp(&onlyB.pixels[i], &ground.pixels[i], 3) != 0;
        pixelsA += inA, pixelsB += inB;
        if (inA == inB) continue;  // neither, or both overlapping (depth decides)
        ++covered;
        matching += std::memcmp(&both.pixels[i], inA ? &onlyA.pixels[i] : &onlyB.pixels[i], 3) == 0;
    }
    EXPECT_GT(pixelsA, 100u);
    EXPECT_GT(pixelsB, 100u);
    EXPECT_GE(static_cast<double>(matching), 0.999 * static_cast<double>(covered));
    for (VkFence fence : fences) vkDestroyFence(context->device, fence, nullptr);
    vkFreeCommandBuffers(context->device, context->commandPool, 2, cmds.data());
}

// What memoryNeeded promises before a renderer exists is what the renderer then allocates, within 1 %,
// for every method, with and without impostors.
TEST_F(GpuTest, MemoryNeededMatchesWhatTheRendererAllocates) {
    crowdgpu::Crowd crowd = defaultCrowd(300);
    HostDevice host(*context);
    for (const bool impostors : {false, true})
        for (const crowdgpu::Method method :
             {crowdgpu::Method::TwoPass, crowdgpu::Method::TwoPassDirect, crowdgpu::Method::VertexShader,
              crowdgpu::Method::VertexShaderInstanced, crowdgpu::Method::Compute, crowdgpu::Method::Static}) {
            if (method == crowdgpu::Method::TwoPassDirect && !context->fragmentStores) continue;
            crowdgpu::RendererSettings settings;
            settings.method = method;
            settings.impostors = impostors;
            settings.meshCapacity = 100;
            const std::uint64_t needed = crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings);
            crowdgpu::Renderer renderer(host.device, crowd, settings);
            std::uint64_t allocated = 0;
            for (const crowdgpu::MemoryItem& item : renderer.memory()) allocated += item.bytes;
            EXPECT_NEAR(static_cast<double>(needed), static_cast<double>(allocated), 0.01 * static_cast<double>(allocated))
                << "method " << static_cast<int>(method) << ", impostors " << impostors;
        }
}

// Bad use: one clear error with its code, and nothing made.
TEST_F(GpuTest, LibraryRefusesBadUseWithOneClearError) {
    crowdgpu::Crowd crowd = defaultCrowd(16);
    auto expectError = [](crowdgpu::ErrorCode code, const std::string& words, auto&& call) {
        try {
            call();
            ADD_FAILURE() << "no error for: " << words;
        } catch (const crowdgpu::Error& error) {
            EXPECT_EQ(error.code(), code) << error.what();
            EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
            EXPECT_EQ(std::string(error.what()).find("--"), std::string::npos) << "CLI vocabulary: " << error.what();
        }
    };
    {  // a device created without a feature the library needs
        HostDevice host(*context);
        host.vulkan12.drawIndirectCount = VK_FALSE;
        expectError(crowdgpu::ErrorCode::Unsupported, "drawIndirectCount",
                    [&] { crowdgpu::Renderer(host.device, crowd, {}); });
        host.device.enabledFeatures = nullptr;
        expectError(crowdgpu::ErrorCode::InvalidArgument, "enabledFeatures",
                    [&] { crowdgpu::Renderer(host.device, crowd, {}); });
    }
    HostDevice host(*context);
    {  // formats the device cannot render to
        crowdgpu::RendererSettings settings;
        settings.target.color = VK_FORMAT_D32_SFLOAT;
        expectError(crowdgpu::ErrorCode::Unsupported, "colour format", [&] { crowdgpu::Renderer(host.device, crowd, settings); });
        settings.target = {};
        settings.target.depth = VK_FORMAT_R8G8B8A8_UNORM;
        expectError(crowdgpu::ErrorCode::Unsupported, "depth format", [&] { crowdgpu::Renderer(host.device, crowd, settings); });
        settings.target = {};
        settings.lodThresholds[0] = 10.0f;
        expectError(crowdgpu::ErrorCode::InvalidArgument, "LOD thresholds",
                    [&] { crowdgpu::Renderer(host.device, crowd, settings); });
    }
    {  // record calls out of order, before setup, in a slot that does not exist, with a broken view
        crowdgpu::Renderer renderer(host.device, crowd, {});
        const crowdgpu::FrameView view = defaultView(crowd, {64, 64}, 0.0f);
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            expectError(crowdgpu::ErrorCode::WrongOrder, "recordSetup", [&] { renderer.recordCompute(cmd, 0, view, crowd); });
        });
        runSetup(*context, renderer);
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            expectError(crowdgpu::ErrorCode::WrongOrder, "recordCompute", [&] { renderer.recordCharacters(cmd, 0); });
            expectError(crowdgpu::ErrorCode::WrongOrder, "recordCompute", [&] { renderer.recordShadows(cmd, 1); });
            expectError(crowdgpu::ErrorCode::InvalidArgument, "slot 2", [&] { renderer.recordCompute(cmd, 2, view, crowd); });
            crowdgpu::FrameView broken = view;
            broken.projection[0] = std::nanf("");
            expectError(crowdgpu::ErrorCode::InvalidArgument, "perspective", [&] { renderer.recordCompute(cmd, 0, broken, crowd); });
            crowdgpu::FrameView empty = view;
            empty.viewport.extent.height = 0;
            expectError(crowdgpu::ErrorCode::InvalidArgument, "viewport is empty", [&] { renderer.recordCompute(cmd, 0, empty, crowd); });
            crowdgpu::FrameView wide = view;
            wide.viewport.extent.width = context->properties.limits.maxViewportDimensions[0] + 1;
            expectError(crowdgpu::ErrorCode::InvalidArgument, "maxViewportDimensions",
                        [&] { renderer.recordCompute(cmd, 0, wide, crowd); });
            renderer.recordCompute(cmd, 0, view, crowd);
            expectError(crowdgpu::ErrorCode::WrongOrder, "recordShadows", [&] { renderer.recordCharacters(cmd, 0); });
            // The edge filter, asked of a renderer made without it.
            expectError(crowdgpu::ErrorCode::WrongOrder, "edgeFilter",
                        [&] { renderer.recordEdgeFilter(cmd, 0, VK_NULL_HANDLE, VK_NULL_HANDLE, {64, 64}); });
        });
    }
    {  // the edge filter with views it cannot use, or a slot that does not exist
        crowdgpu::RendererSettings settings;
        settings.edgeFilter = true;
        crowdgpu::Renderer renderer(host.device, crowd, settings);
        const auto view = reinterpret_cast<VkImageView>(std::uintptr_t{1});  // never reached: refused first
        gpu::runOneShotNow(*context, [&](VkCommandBuffer cmd) {
            expectError(crowdgpu::ErrorCode::InvalidArgument, "different destination",
                        [&] { renderer.recordEdgeFilter(cmd, 0, view, view, {64, 64}); });
            expectError(crowdgpu::ErrorCode::InvalidArgument, "source view",
                        [&] { renderer.recordEdgeFilter(cmd, 0, VK_NULL_HANDLE, view, {64, 64}); });
            expectError(crowdgpu::ErrorCode::InvalidArgument, "slot 2",
                        [&] { renderer.recordEdgeFilter(cmd, 2, view, VK_NULL_HANDLE, {64, 64}); });
        });
    }
    {  // a crowd larger than the device's memory, refused before anything is allocated
        crowdgpu::GridLayout layout;
        layout.count = 2'000'000;
        crowdgpu::Crowd huge = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
        crowdgpu::RendererSettings settings;
        settings.method = crowdgpu::Method::Static;  // every character at every LOD: far past any heap here
        ASSERT_GT(crowdgpu::memoryNeeded(context->physicalDevice, huge, settings), context->deviceLocalBytes());
        expectError(crowdgpu::ErrorCode::OutOfDeviceMemory, "2000000 characters",
                    [&] { crowdgpu::Renderer(host.device, huge, settings); });
    }
}

// README.md's Embedding block, run as written: its crowd (crowd-render's default: 1,024 soldiers) in the
// test's own B8G8R8A8_SRGB + D32 pass, one frame, validation on. The renderer counts the characters it
// drew, and wherever the frame is not the cleared sky it is crowd-render's picture of the same crowd,
// camera and time (the block draws no ground).
TEST_F(GpuTest, ReadmeEmbeddingBlockDrawsTheCrowd) {
    const VkExtent2D size{256, 144};
    const std::string png = test::artifactPath("library-readme-crowd-render.png");
    // Single-sampled: the block's colour pass is (its pipelines are made for its target's one sample).
    const test::ProgramResult r =
        test::runProgram(CROWD_RENDER_BINARY, "--aa off --frames 1 --size 256x144 --validation --out " + png);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const app::Rgba8Image program = readPng(png);
    ASSERT_EQ(program.width, size.width);

    HostDevice host(*context);
    gpu::Image color = gpu::createImage2D(*context, size, VK_FORMAT_B8G8R8A8_SRGB,
                                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                          "readme colour");
    gpu::Image depth = gpu::createImage2D(*context, size, VK_FORMAT_D32_SFLOAT,
                                          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "readme depth");
    VkCommandBuffer cmds[2];  // the block's setupCmd and cmd
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = context->commandPool;
    allocate.commandBufferCount = 2;
    ASSERT_EQ(vkAllocateCommandBuffers(context->device, &allocate, cmds), VK_SUCCESS);
    VkFence fence;
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    ASSERT_EQ(vkCreateFence(context->device, &fenceInfo, nullptr, &fence), VK_SUCCESS);
    const auto submitAndWait = [&](VkCommandBuffer cmd) {
        ASSERT_EQ(vkEndCommandBuffer(cmd), VK_SUCCESS);
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        ASSERT_EQ(vkQueueSubmit(context->queue, 1, &submit, fence), VK_SUCCESS);
        ASSERT_EQ(vkWaitForFences(context->device, 1, &fence, VK_TRUE, UINT64_MAX), VK_SUCCESS);
        vkResetFences(context->device, 1, &fence);
    };
    for (VkCommandBuffer cmd : cmds) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        ASSERT_EQ(vkBeginCommandBuffer(cmd, &begin), VK_SUCCESS);
    }

    // The host's colour pass, its images made ready in the frame's command buffer before the block.
    const VkPipelineStageFlags2 depthTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    gpu::imageBarrier(cmds[1], color.image, VK_IMAGE_ASPECT_COLOR_BIT, {VK_PIPELINE_STAGE_2_NONE, 0},
                      {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    gpu::imageBarrier(cmds[1], depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, {VK_PIPELINE_STAGE_2_NONE, 0},
                      {depthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo colorAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    colorAttachment.imageView = color.view;
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    const float sky[4] = {crowdgpu::kHorizonColor[0], crowdgpu::kHorizonColor[1], crowdgpu::kHorizonColor[2], 1.0f};
    std::memcpy(colorAttachment.clearValue.color.float32, sky, sizeof sky);
    VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depth.view;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo yourColourPass{VK_STRUCTURE_TYPE_RENDERING_INFO};
    yourColourPass.renderArea = {{0, 0}, size};
    yourColourPass.layerCount = 1;
    yourColourPass.colorAttachmentCount = 1;
    yourColourPass.pColorAttachments = &colorAttachment;
    yourColourPass.pDepthAttachment = &depthAttachment;

    std::uint32_t drawn = 0;
    const auto frameRecorded = [&](crowdgpu::Renderer& renderer) {
        gpu::imageBarrier(cmds[1], color.image, VK_IMAGE_ASPECT_COLOR_BIT,
                          {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                          {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT},
                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        submitAndWait(cmds[1]);
        const crowdgpu::FrameCounts counts = renderer.counts(0);
        drawn = counts.characters[0] + counts.characters[1] + counts.characters[2];
    };
    // The block builds its own crowd: the view is of the same crowd built here.
    const crowdgpu::FrameView view = defaultView(defaultCrowd(1024), size, 0.0f);
    readme::embeddingExample(host.device, submitAndWait, cmds[0], cmds[1], 0, view, 0.0, yourColourPass, frameRecorded);
    const app::Rgba8Image frame = readBgraImage(*context, color);

    EXPECT_GT(drawn, 0u);
    std::size_t crowdPixels = 0, matching = 0;
    // The clear colour as the sRGB target stores it.
    const auto srgb = [](float linear) {
        const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
        return static_cast<int>(std::lround(255.0f * encoded));
    };
    const int skyPixel[3] = {srgb(sky[0]), srgb(sky[1]), srgb(sky[2])};
    for (std::size_t i = 0; i < frame.pixels.size(); i += 4) {
        bool isSky = true;
        for (int c = 0; c < 3; ++c) isSky = isSky && std::abs(int(frame.pixels[i + c]) - skyPixel[c]) <= 1;
        if (isSky) continue;
        ++crowdPixels;
        bool same = true;
        for (int c = 0; c < 3; ++c) same = same && std::abs(int(frame.pixels[i + c]) - int(program.pixels[i + c])) <= 1;
        matching += same;
    }
    EXPECT_GT(crowdPixels, frame.pixels.size() / 4 / 20) << "the crowd covers under 5 % of the frame";
    EXPECT_GE(static_cast<double>(matching), 0.999 * static_cast<double>(crowdPixels));

    vkDestroyFence(context->device, fence, nullptr);
    vkFreeCommandBuffers(context->device, context->commandPool, 2, cmds);
    gpu::destroyImage(*context, depth);
    gpu::destroyImage(*context, color);
    std::filesystem::remove(png);
}
