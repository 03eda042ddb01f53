// The host's world on the GPU, through the public API as a game drives it (tests/support/host_frames.h):
// a population that changes every frame draws what a crowd built fresh from its survivors draws; a spawn
// past the capacity is refused (it once wrote out of bounds); frames dropped at random leave no trace;
// characters driven from the host's memory and from a device buffer are drawn where their samples put
// them. Lavapipe, validation and synchronization validation silent.
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "app/png_writer.h"
#include "crowdgpu/renderer.hpp"
#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "support/gpu_test.h"
#include "support/host_frames.h"

namespace {

using test::GpuTest;

constexpr VkExtent2D kSize{192, 108};
constexpr double kFrame = 1.0 / 60.0;

crowdgpu::FrameView viewOf(double time) {
    const float eye[3] = {0.0f, 9.0f, 17.0f}, target[3] = {0.0f, 0.5f, 0.0f};
    return crowdgpu::lookAt(eye, target, 0.8f, 0.1f, 200.0f, kSize, time);
}

crowdgpu::RendererSettings settings() {
    crowdgpu::RendererSettings s;
    s.target = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    s.method = crowdgpu::Method::Compute;
    s.ground = s.sky = true;
    s.shadowMapSize = 512;  // lavapipe's frames, a fifth of the default's
    return s;
}

// Candidate character k: in place, on a 12 x 8 grid, everything chosen (props and tint too), so that it
// moves and looks the same whichever slot it takes.
crowdgpu::Character candidate(std::uint32_t k) {
    crowdgpu::Character c;
    c.position[0] = -8.25f + 1.5f * static_cast<float>(k % 12);
    c.position[2] = -5.25f + 1.5f * static_cast<float>(k / 12);
    c.heading = 0.4f * static_cast<float>(k % 7);
    c.phase = 0.13f * static_cast<float>(k);
    c.speed = 0.9f + 0.02f * static_cast<float>(k % 10);
    c.tint[0] = 0.7f + 0.03f * static_cast<float>(k % 9);
    c.props = k % 3 == 0 ? 1u : 0u;
    return c;
}

const float kWorldLo[3] = {-10.0f, 0.0f, -7.0f}, kWorldHi[3] = {10.0f, 0.0f, 7.0f};

// The picture of a crowd built fresh from `characters`, at `time`.
app::Rgba8Image freshPicture(const gpu::VulkanContext& context, const app::HostDevice& device,
                             const std::vector<crowdgpu::Character>& characters, double time) {
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, characters);
    crowd.setWorldBounds(kWorldLo, kWorldHi);
    test::LentDevice host(context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(context, device, kSize, settings().target);
    frames.setup(renderer);
    crowd.advanceTo(time);
    frames.frame(renderer, crowd, viewOf(time));
    return frames.finish();
}

std::size_t differingPixels(const app::Rgba8Image& a, const app::Rgba8Image& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4) n += std::memcmp(&a.pixels[i], &b.pixels[i], 3) != 0;
    return n;
}

TEST_F(GpuTest, ACrowdThatChangesEveryFrameDrawsWhatAFreshCrowdOfItsSurvivorsDraws) {
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {40};
    std::vector<crowdgpu::Character> initial;
    for (std::uint32_t k = 0; k < 20; ++k) initial.push_back(candidate(k));
    crowdgpu::Crowd live({crowdgpu::Model::soldier(1)}, initial, crowdgpu::Behaviour::InPlace, 1, capacity);
    live.setWorldBounds(kWorldLo, kWorldHi);
    std::map<std::uint32_t, std::uint32_t> who;  // slot -> candidate
    std::vector<crowdgpu::CharacterHandle> living;
    for (std::uint32_t k = 0; k < 20; ++k) who[k] = k, living.push_back(live.handle(k));
    test::LentDevice host(*context);
    crowdgpu::Renderer renderer(host.device, live, settings());
    test::HostFrames frames(*context, *device, kSize, settings().target);
    frames.setup(renderer);
    std::mt19937 random(7);
    std::uint32_t nextCandidate = 20;
    for (std::uint32_t frame = 0; frame < 300; ++frame) {
        // Every frame: one to three leave, one to three come (while slots are free).
        for (std::uint32_t n = 1 + random() % 3; n > 0 && !living.empty(); --n) {
            const std::size_t i = random() % living.size();
            live.remove(living[i]);
            who.erase(living[i].slot);
            living.erase(living.begin() + static_cast<std::ptrdiff_t>(i));
        }
        for (std::uint32_t n = 1 + random() % 3; n > 0 && live.liveCount() < 40; --n) {
            const std::uint32_t k = nextCandidate++ % 96;
            const crowdgpu::CharacterHandle h = live.spawn(candidate(k));
            who[h.slot] = k;
            living.push_back(h);
        }
        const double time = frame * kFrame;
        live.advanceTo(time);
        frames.frame(renderer, live, viewOf(time));
        if (frame != 99 && frame != 299) continue;
        const app::Rgba8Image picture = frames.finish();
        std::vector<crowdgpu::Character> survivors;
        for (const auto& [slot, k] : who) survivors.push_back(candidate(k));
        std::reverse(survivors.begin(), survivors.end());  // in another order than the slots'
        const app::Rgba8Image fresh = freshPicture(*context, *device, survivors, time);
        const std::size_t differ = differingPixels(picture, fresh);
        std::printf("frame %u: %zu living, %zu of %zu pixels differ from the fresh crowd's\n", frame, survivors.size(),
                    differ, picture.pixels.size() / 4);
        EXPECT_EQ(differ, 0u) << "frame " << frame;
        if (differ != 0) {
            app::writePng(test::artifactPath("live-crowd-" + std::to_string(frame) + ".png"), picture);
            app::writePng(test::artifactPath("live-crowd-fresh-" + std::to_string(frame) + ".png"), fresh);
        }
    }
    EXPECT_EQ(renderer.framesLost(), 0u);
}

TEST_F(GpuTest, ASpawnPastTheCapacityIsRefusedAndTheCrowdStillDrawsRight) {
    // Spawning after the renderer existed once wrote past the animation pass's buffers: now a crowd's
    // slots are fixed when it is made, and a spawn past them is refused with its own code.
    std::vector<crowdgpu::Character> initial;
    for (std::uint32_t k = 0; k < 12; ++k) initial.push_back(candidate(k));
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, initial);
    crowd.setWorldBounds(kWorldLo, kWorldHi);
    test::LentDevice host(*context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(*context, *device, kSize, settings().target);
    frames.setup(renderer);
    crowd.advanceTo(0.5);
    frames.frame(renderer, crowd, viewOf(0.5));
    try {
        crowd.spawn(candidate(40));
        ADD_FAILURE() << "a spawn past the capacity was accepted";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::CapacityExceeded) << e.what();
    }
    crowd.advanceTo(1.0);
    frames.frame(renderer, crowd, viewOf(1.0));
    EXPECT_EQ(differingPixels(frames.finish(), freshPicture(*context, *device, initial, 1.0)), 0u);
    // A removal frees a slot the next spawn takes, after the renderer was made: drawn as a fresh crowd draws it.
    crowd.remove(crowd.handle(3));
    crowd.spawn(candidate(40));
    crowd.advanceTo(1.5);
    frames.frame(renderer, crowd, viewOf(1.5));
    std::vector<crowdgpu::Character> now = initial;
    now[3] = candidate(40);
    EXPECT_EQ(differingPixels(frames.finish(), freshPicture(*context, *device, now, 1.5)), 0u);
}

// The same 600 frames of a milling crowd that changes (spawns, removals, driven characters' samples),
// dropping frames at random (recorded, never submitted) or none; the frames after the last drop.
app::Rgba8Image sixHundredFrames(const gpu::VulkanContext& context, const app::HostDevice& device, double dropShare,
                                 std::uint64_t* lost) {
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {48};
    capacity.drivenKeys = crowdgpu::kDrivenKeys;  // the driven walker comes after the crowd is made
    crowdgpu::GridLayout layout;
    layout.count = 16;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout, crowdgpu::Behaviour::Mill, capacity);
    crowd.setWorldBounds(kWorldLo, kWorldHi);
    crowdgpu::Character walker;
    walker.motion = crowdgpu::MotionSource::HostSamples;
    walker.props = 0;
    const crowdgpu::CharacterHandle driven = crowd.spawn(walker);
    test::LentDevice host(context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(context, device, kSize, settings().target);
    frames.setup(renderer);
    std::mt19937 changes(3), drops(11);
    std::vector<crowdgpu::CharacterHandle> spawned;
    for (std::uint32_t frame = 0; frame < 600; ++frame) {
        const double time = frame * kFrame;
        if (changes() % 4 == 0 && crowd.liveCount() < 48) spawned.push_back(crowd.spawn(candidate(changes() % 96)));
        if (changes() % 5 == 0 && !spawned.empty()) {
            crowd.remove(spawned.front());
            spawned.erase(spawned.begin());
        }
        // The driven one walks a circle, a sample every other frame.
        if (frame % 2 == 0) {
            const float x = 4.0f * static_cast<float>(std::cos(0.3 * time)), z = 4.0f * static_cast<float>(std::sin(0.3 * time));
            crowd.drive({&driven, &time, &x, &z, nullptr, 1});
        }
        crowd.advanceTo(time);
        const bool drop = frame < 590 && std::uniform_real_distribution<double>(0.0, 1.0)(drops) < dropShare;
        frames.frame(renderer, crowd, viewOf(time), drop);
    }
    const app::Rgba8Image picture = frames.finish();
    *lost = renderer.framesLost();
    return picture;
}

TEST_F(GpuTest, FramesDroppedAtRandomLeaveNoTrace) {
    std::uint64_t lostNone = 0, lost = 0;
    const app::Rgba8Image none = sixHundredFrames(*context, *device, 0.0, &lostNone);
    const app::Rgba8Image dropped = sixHundredFrames(*context, *device, 0.3, &lost);
    EXPECT_EQ(lostNone, 0u);
    EXPECT_GT(lost, 100u) << "about 30 % of 590 frames were dropped";
    const std::size_t differ = differingPixels(none, dropped);
    std::printf("%llu frames dropped of 600; %zu pixels differ\n", static_cast<unsigned long long>(lost), differ);
    EXPECT_EQ(differ, 0u);
    if (differ != 0) {
        app::writePng(test::artifactPath("dropped-frames-none.png"), none);
        app::writePng(test::artifactPath("dropped-frames-dropped.png"), dropped);
    }
}

// Characters driven along straight east-west lines, from the host's memory or from a device buffer the
// test writes each frame (as a host's simulation pass would): the same samples, the same picture.
struct LineSamples {
    std::vector<crowdgpu::CharacterHandle> handles;
    std::vector<double> times;
    std::vector<float> x, z;
    void at(double time, std::uint32_t n) {
        handles.resize(n), times.assign(n, time), x.resize(n), z.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            handles[i] = {i, 1};
            x[i] = -6.0f + static_cast<float>(i % 3) + 1.3f * static_cast<float>(time) * (i % 2 ? 1.0f : 0.5f);
            z[i] = -4.0f + 1.2f * static_cast<float>(i);
        }
    }
};

app::Rgba8Image drivenPicture(const gpu::VulkanContext& context, const app::HostDevice& device, bool fromDevice,
                              crowdgpu::FrameCounts* counts) {
    constexpr std::uint32_t kCount = 8;
    crowdgpu::Character c;
    c.motion = fromDevice ? crowdgpu::MotionSource::DeviceSamples : crowdgpu::MotionSource::HostSamples;
    c.props = 0;
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, std::vector<crowdgpu::Character>(kCount, c));
    crowd.setWorldBounds(kWorldLo, kWorldHi);
    test::LentDevice host(context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(context, device, kSize, settings().target);
    frames.setup(renderer);
    gpu::Buffer buffer = gpu::createBuffer(context, kCount * sizeof(crowdgpu::DeviceSample),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           gpu::MemoryUse::DeviceLocal, "test device samples");
    const crowdgpu::DeviceSamples samples{buffer.buffer, 0, buffer.size};
    LineSamples line;
    for (std::uint32_t frame = 0; frame < 90; ++frame) {
        const double time = frame * kFrame;
        line.at(time, kCount);
        if (fromDevice) {
            std::vector<crowdgpu::DeviceSample> written(kCount);
            for (std::uint32_t i = 0; i < kCount; ++i) written[i] = {0.0f, line.x[i], line.z[i], std::nanf("")};
            crowd.advanceTo(time);
            frames.frame(renderer, crowd, viewOf(time), false, &samples, [&](VkCommandBuffer cmd) {
                // The host's pass: here a copy into its buffer, then the barrier the header asks for.
                gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                                   {VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
                vkCmdUpdateBuffer(cmd, buffer.buffer, 0, written.size() * sizeof(crowdgpu::DeviceSample), written.data());
                gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                                   {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT});
            });
        } else {
            crowd.drive({line.handles.data(), line.times.data(), line.x.data(), line.z.data(), nullptr, kCount});
            crowd.advanceTo(time);
            frames.frame(renderer, crowd, viewOf(time));
        }
    }
    const app::Rgba8Image picture = frames.finish();
    *counts = renderer.counts(frames.lastSlot());
    gpu::destroyBuffer(context, buffer);
    return picture;
}

TEST_F(GpuTest, DeviceSamplesDriveCharactersAsTheHostsSamplesDo) {
    crowdgpu::FrameCounts hostCounts{}, deviceCounts{};
    const app::Rgba8Image fromHost = drivenPicture(*context, *device, false, &hostCounts);
    const app::Rgba8Image fromDevice = drivenPicture(*context, *device, true, &deviceCounts);
    EXPECT_EQ(deviceCounts.deviceSamples.applied, 8u) << "a sample a character a frame";
    EXPECT_EQ(deviceCounts.deviceSamples.late + deviceCounts.deviceSamples.refused, 0u);
    // The keys are made on the GPU there, on the CPU here: the same rules in float, a few pixels apart at most.
    EXPECT_GE(test::fractionOfMatchingPixels(fromHost, fromDevice, 2), 0.999);
    app::writePng(test::artifactPath("driven-host.png"), fromHost);
    app::writePng(test::artifactPath("driven-device.png"), fromDevice);
}

TEST_F(GpuTest, DrivenCharactersAreDrawnWhereTheCpuSaysTheyAre) {
    // The motion pass's records against the crowd's CPU state, character by character, on a terrain.
    const model::SkinnedModel soldier = test::loadModel("soldier", 1);
    crowd::Character c;
    c.driven = crowd::Driven::HostSamples;
    c.props = 0;
    std::vector<crowd::Character> characters(6, c);
    crowd::Character standing;  // and two the behaviour keeps in place, on the slope too
    standing.props = 0;
    standing.position = {-2.0f, 0.0f, 1.5f};
    characters.push_back(standing);
    standing.position = {4.5f, 0.0f, -2.5f};
    characters.push_back(standing);
    crowd::Crowd crowd({&soldier}, characters);
    // A tilted plane with a bump: every character stands at its own height.
    crowd::Heightfield field{5, 4, {}, {-4.0f, -3.0f}, {12.0f, 6.0f}};
    for (std::uint32_t r = 0; r < field.rows; ++r)
        for (std::uint32_t col = 0; col < field.columns; ++col)
            field.heights.push_back(0.3f * static_cast<float>(col) - 0.2f * static_cast<float>(r) + (col == 2 && r == 1 ? 0.8f : 0.0f));
    crowd.setTerrain(crowd::Terrain(field));
    test::RendererOptions options;
    options.size = {96, 64};
    options.method = skin::Method::Compute;
    test::TestRenderer renderer(*context, crowd, options);
    for (int k = 0; k <= 60; ++k) {
        const double time = k * 0.05;
        for (std::uint32_t i = 0; i < 6; ++i) {
            const crowd::Handle h[1] = {{i, 1}};
            const double t[1] = {time};
            const float x[1] = {1.1f * static_cast<float>(i) + static_cast<float>(time) * 0.4f * static_cast<float>(i)};
            const float z[1] = {static_cast<float>(std::sin(time + i))};
            crowd.drive({h, t, x, z, {}});
        }
        renderer.renderFrame(time);
    }
    renderer.finish();
    const std::vector<gpu::CharacterRecord> records = test::readAll<gpu::CharacterRecord>(*context, renderer.buffers().characters());
    for (std::uint32_t i = 0; i < characters.size(); ++i) {
        const crowd::MotionState state = crowd.stateAt(i, 3.0);
        EXPECT_NEAR(records[i].placement.x, state.position.x, 1e-5f) << i;
        EXPECT_NEAR(records[i].placement.y, state.position.y, 1e-5f) << i;  // on the terrain, as the CPU says
        EXPECT_NEAR(records[i].placement.z, state.position.z, 1e-5f) << i;
        EXPECT_NEAR(records[i].placement.w, state.heading, 1e-5f) << i;
        EXPECT_NEAR(records[i].pose.x, state.phase, 1e-5f) << i;
        EXPECT_EQ(records[i].ids.w, state.clipFrom | (state.clipTo << 16)) << i;
    }
}

// The crowd of the first candidates on a terrain of constant height h, seen from `lift` metres up.
app::Rgba8Image plateauPicture(const gpu::VulkanContext& context, const app::HostDevice& device, float h, float lift) {
    std::vector<crowdgpu::Character> characters;
    for (std::uint32_t k = 0; k < 24; ++k) characters.push_back(candidate(k * 4));
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, characters);
    crowd.setWorldBounds(kWorldLo, kWorldHi);
    const float heights[4] = {h, h, h, h};
    if (h != 0.0f) crowd.setTerrain({2, 2, heights, {-30.0f, -30.0f}, {60.0f, 60.0f}});
    test::LentDevice host(context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(context, device, kSize, settings().target);
    frames.setup(renderer);
    crowd.advanceTo(0.5);
    const float eye[3] = {0.0f, 9.0f + lift, 17.0f}, target[3] = {0.0f, 0.5f + lift, 0.0f};
    frames.frame(renderer, crowd, crowdgpu::lookAt(eye, target, 0.8f, 0.1f, 200.0f, kSize, 0.5));
    return frames.finish();
}

TEST_F(GpuTest, APlateauIsTheFlatWorldRaised) {
    // Characters, their shadows and the ground drawn as the terrain, 3 m up, seen from 3 m higher: the
    // picture of the flat world. The sunlight on a terrain's ground is the shadow map compared at each
    // pixel rather than read from the ground sunlight image (made for the plane y = 0), so the pixels of
    // the characters' shadows on the ground differ: 2.2 % of the picture here, nothing else.
    const app::Rgba8Image flat = plateauPicture(*context, *device, 0.0f, 0.0f);
    const app::Rgba8Image raised = plateauPicture(*context, *device, 3.0f, 3.0f);
    const app::Rgba8Image unseen = plateauPicture(*context, *device, 3.0f, 0.0f);  // the terrain does something
    app::writePng(test::artifactPath("terrain-plateau.png"), raised);
    EXPECT_GE(test::fractionOfMatchingPixels(flat, raised, 3), 0.97);
    EXPECT_LT(test::fractionOfMatchingPixels(flat, unseen, 3), 0.9);
}

TEST_F(GpuTest, ADeviceBufferTooSmallIsRefusedBeforeAnythingIsRecorded) {
    crowdgpu::Character c;
    c.motion = crowdgpu::MotionSource::DeviceSamples;
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, std::vector<crowdgpu::Character>(4, c));
    test::LentDevice host(*context);
    crowdgpu::Renderer renderer(host.device, crowd, settings());
    test::HostFrames frames(*context, *device, kSize, settings().target);
    frames.setup(renderer);
    gpu::Buffer small = gpu::createBuffer(*context, 3 * sizeof(crowdgpu::DeviceSample), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          gpu::MemoryUse::DeviceLocal, "test device samples (too few)");
    const crowdgpu::DeviceSamples samples{small.buffer, 0, small.size};
    try {
        frames.frame(renderer, crowd, viewOf(0.0), true, &samples);
        ADD_FAILURE() << "a buffer of 3 samples for 4 slots was accepted";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
        EXPECT_NE(std::string(e.what()).find("need"), std::string::npos) << e.what();
    }
    // The renderer still draws.
    crowd.advanceTo(0.1);
    frames.frame(renderer, crowd, viewOf(0.1));
    frames.finish();
    gpu::destroyBuffer(*context, small);
}

}  // namespace
