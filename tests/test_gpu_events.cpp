// The GPU event buffer (render/event_pass.h, docs/events.md): each frame's list of the events that
// characters in view fire equals crowd::Crowd::events for those characters and that window (the CPU
// reference, in double), with positions at Crowd::jointWorld's; a full buffer keeps its capacity's
// worth and counts the rest.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <tuple>

#include <gtest/gtest.h>

#include "crowd/epoch.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;

constexpr double kFrame = 1.0 / 60.0;
// Float on the epoch's clock against double: a firing time within this of the CPU's (measured: about
// 2e-6 s), and an event this close to a frame's edge may land in the frame beside it.
constexpr double kTimeTolerance = 1e-4;

std::uint32_t jointNamed(const model::SkinnedModel& model, const std::string& name) {
    const auto& names = model.skeleton.jointNames;
    const auto it = std::find(names.begin(), names.end(), name);
    EXPECT_NE(it, names.end()) << name;
    return static_cast<std::uint32_t>(it - names.begin());
}

// The soldier with footsteps on its walk and run (at the feet, a quarter and 0.7 of the walk's cycle,
// 0.15 and 0.62 of the run's, as a glTF file's extras would set them) and a breath on its idle with no
// joint (placed at the root).
model::SkinnedModel soldierWithEvents() {
    model::SkinnedModel soldier = test::loadModel("soldier", 1);
    const auto left = static_cast<std::int32_t>(jointNamed(soldier, "foot_l"));
    const auto right = static_cast<std::int32_t>(jointNamed(soldier, "foot_r"));
    for (anim::Clip& clip : soldier.clips) {
        if (clip.name == "walk")
            clip.events = {{"step.left", 0.25f * clip.duration, left}, {"step.right", 0.7f * clip.duration, right}};
        // The run's steps lie elsewhere in its cycle, so a walk <-> run crossfade fires each pair
        // where the phase meets a point that moves with the weight (crowd/event_pairs.h).
        if (clip.name == "run")
            clip.events = {{"step.left", 0.15f * clip.duration, left}, {"step.right", 0.62f * clip.duration, right}};
        if (clip.name == "idle") clip.events = {{"breath", 0.5f * clip.duration, -1}};
    }
    return soldier;
}

struct GpuFrameEvents {
    gpu::EventHeader header{};
    std::vector<gpu::EventRecord> records;
};

GpuFrameEvents readEvents(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.recorder().eventPass()->events());
    GpuFrameEvents result;
    std::memcpy(&result.header, bytes.data(), sizeof result.header);
    result.records.resize(std::min(result.header.count, result.header.capacity));
    std::memcpy(result.records.data(), bytes.data() + sizeof result.header, result.records.size() * sizeof(gpu::EventRecord));
    return result;
}

std::vector<std::uint32_t> charactersInView(const gpu::VulkanContext& context, const test::TestRenderer& renderer) {
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.drawLists().shadowStates());
    std::vector<std::uint32_t> inView;
    for (std::uint32_t c = 0; c < renderer.drawLists().characterCount(); ++c) {
        std::uint32_t state = 0;
        std::memcpy(&state, bytes.data() + c * sizeof state, sizeof state);
        if (state & SHADOW_IN_VIEW_BIT) inView.push_back(c);
    }
    return inView;
}

// An event of either list in one frame: who, which, when (scene seconds) and where.
struct Fired {
    std::uint32_t character, clip, event;
    double time;
    glm::vec3 place{0.0f};
};
bool sameEvent(const Fired& a, const Fired& b) {
    return a.character == b.character && a.clip == b.clip && a.event == b.event && std::abs(a.time - b.time) < kTimeTolerance;
}
bool byWhoAndWhen(const Fired& a, const Fired& b) {
    return std::tie(a.character, a.clip, a.event, a.time) < std::tie(b.character, b.clip, b.event, b.time);
}

struct Comparison {
    std::size_t matched = 0, nearEdge = 0, beforeReplan = 0, inCrossfade = 0;
    std::size_t paired = 0;  // of those in crossfades, fired by a walk <-> run pair (a moving point)
    double worstTime = 0.0, worstPlace = 0.0, worstPlaceInCrossfade = 0.0;
};

// Matches one frame's GPU events to the CPU's; an event in one list only must lie within
// kTimeTolerance of the window's edge (float rounding put it in the frame beside).
void compareFrame(const crowd::Crowd& crowd, const model::SkinnedModel& soldier, std::vector<Fired> gpuEvents,
                  std::vector<Fired> cpuEvents, double from, double to, Comparison& out) {
    std::sort(gpuEvents.begin(), gpuEvents.end(), byWhoAndWhen);
    std::sort(cpuEvents.begin(), cpuEvents.end(), byWhoAndWhen);
    auto nearEdge = [&](const Fired& e) { return std::abs(e.time - from) < kTimeTolerance || std::abs(e.time - to) < kTimeTolerance; };
    std::vector<bool> used(gpuEvents.size(), false);
    for (const Fired& cpu : cpuEvents) {
        std::size_t found = gpuEvents.size();
        for (std::size_t i = 0; i < gpuEvents.size(); ++i)
            if (!used[i] && sameEvent(gpuEvents[i], cpu)) found = i, i = gpuEvents.size();
        if (found == gpuEvents.size()) {
            EXPECT_TRUE(nearEdge(cpu)) << "character " << cpu.character << " clip " << cpu.clip << " event " << cpu.event
                                       << " at " << cpu.time << " s: missing from the GPU's list";
            out.nearEdge += 1;
            continue;
        }
        used[found] = true;
        const Fired& gpu = gpuEvents[found];
        ++out.matched;
        out.worstTime = std::max(out.worstTime, std::abs(gpu.time - cpu.time));
        if (cpu.time < crowd.plans()[cpu.character].start) ++out.beforeReplan;
        // Where: the event's joint (its root without one) as Crowd::jointWorld places it then.
        const std::int32_t joint = soldier.clips[cpu.clip].events[cpu.event].joint;
        glm::vec3 expected = crowd.stateKnown(cpu.character, cpu.time).position;
        if (joint >= 0) {
            const anim::Affine world = crowd.jointWorld(cpu.character, static_cast<std::uint32_t>(joint), cpu.time);
            expected = {world.row0.w, world.row1.w, world.row2.w};
        }
        const double error = glm::length(gpu.place - expected);
        const crowd::MotionState state = crowd.stateKnown(cpu.character, cpu.time);
        if (state.weight < 1.0f) {
            ++out.inCrossfade;
            if (!soldier.clips[state.clipFrom].events.empty() && !soldier.clips[state.clipTo].events.empty() &&
                soldier.clips[state.clipFrom].name != "idle" && soldier.clips[state.clipTo].name != "idle")
                ++out.paired;
            out.worstPlaceInCrossfade = std::max(out.worstPlaceInCrossfade, error);
        } else {
            out.worstPlace = std::max(out.worstPlace, error);
        }
    }
    for (std::size_t i = 0; i < gpuEvents.size(); ++i)
        if (!used[i]) {
            EXPECT_TRUE(nearEdge(gpuEvents[i])) << "character " << gpuEvents[i].character << " event at "
                                                << gpuEvents[i].time << " s: on the GPU only";
            out.nearEdge += 1;
        }
}

struct OrbitRun : Comparison {
    std::size_t cpuTotal = 0, outOfView = 0, beforeEpoch = 0, replannedTwice = 0;
};

// A milling crowd of `count` soldiers (walks, stops, crossfades, replans inside frames) seen by a close
// orbiting camera, so characters come into and leave the view: `frames` frames at 60 Hz from `start`,
// each frame's GPU list against Crowd::events for the characters the frame had in view.
// With `walkRunFades` the crowd stands in place instead and every character is commanded to walk, then
// to crossfade between walk and run and back (0.5 s) every 40 frames, at its own frame: walk <-> run
// pairs whose point moves with the weight.
OrbitRun compareAlongAnOrbit(const gpu::VulkanContext& context, test::RendererOptions options, std::uint32_t count,
                             int frames, double start, bool walkRunFades = false) {
    const model::SkinnedModel soldier = soldierWithEvents();
    app::SceneOptions scene;
    scene.count = count;
    crowd::BehaviourSettings behaviour;
    behaviour.kind = walkRunFades ? crowd::Behaviour::InPlace : crowd::Behaviour::Mill;
    behaviour.millRadius = 4.0f;
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene), behaviour);
    std::int32_t walkClip = 0, runClip = 0;
    for (std::uint32_t clip = 0; clip < soldier.clips.size(); ++clip) {
        if (soldier.clips[clip].name == "walk") walkClip = static_cast<std::int32_t>(clip);
        if (soldier.clips[clip].name == "run") runClip = static_cast<std::int32_t>(clip);
    }
    if (walkRunFades)
        for (std::uint32_t c = 0; c < crowd.size(); ++c) crowd.play(c, walkClip, 0.0, 0.0f, 1.0f);
    options.size = {160, 90};
    options.shadows = false;
    test::TestRenderer renderer(context, crowd, options);
    const app::CrowdShape shape = test::shapeOf(crowd);
    OrbitRun run;
    double previous = 0.0;
    for (int frame = 0; frame <= frames; ++frame) {
        const double time = start + frame * kFrame;
        if (walkRunFades)
            for (std::uint32_t c = 0; c < crowd.size(); ++c)
                if ((frame + c) % 40 == 0)
                    crowd.play(c, (frame + c) % 80 == 0 ? runClip : walkClip, time + 0.001, 0.5f, 1.0f);
        // Orbiting, closer than the framing view: the crowd's edges come into and leave the view.
        renderer.camera = app::cameraOnPath(app::CameraPath::Orbit, shape, 160.0f / 90.0f, 8.0 * time);
        renderer.camera.eye = renderer.camera.target + 0.3f * (renderer.camera.eye - renderer.camera.target);
        renderer.renderFrame(time);
        renderer.finish();
        const GpuFrameEvents gpu = readEvents(context, renderer);
        EXPECT_EQ(gpu.header.dropped, 0u);
        EXPECT_EQ(gpu.header.lostSegments, 0u);
        if (frame == 0) {
            EXPECT_EQ(gpu.header.count, 0u);  // the first frame has no window
            previous = time;
            continue;
        }
        const std::vector<std::uint32_t> inView = charactersInView(context, renderer);
        run.outOfView += crowd.size() - inView.size();
        // A character replanned twice in the window is known from its last segment but one on (the
        // CPU refuses earlier times, the GPU fires from there): ask for what it knows.
        std::vector<crowd::FiredEvent> cpu;
        std::vector<std::uint32_t> known;
        for (std::uint32_t c : inView) {
            if (crowd.knownFrom(c) <= previous) known.push_back(c);
            else crowd.events(std::span(&c, 1), crowd.knownFrom(c), time, cpu), ++run.replannedTwice;
        }
        crowd.events(known, previous, time, cpu);
        run.cpuTotal += cpu.size();
        // Fired before the epoch in the frame whose window crosses it.
        const double epoch = crowd::epochOf(time);
        for (const crowd::FiredEvent& e : cpu) run.beforeEpoch += e.time < epoch && previous < epoch ? 1u : 0u;
        std::vector<Fired> cpuEvents, gpuEvents;
        for (const crowd::FiredEvent& e : cpu) cpuEvents.push_back({e.character, e.clip, e.event, e.time});
        for (const gpu::EventRecord& r : gpu.records)
            gpuEvents.push_back({r.ids.x, r.ids.y, r.ids.z, time - static_cast<double>(r.place.w), glm::vec3(r.place)});
        compareFrame(crowd, soldier, gpuEvents, cpuEvents, previous, time, run);
        previous = time;
    }
    std::printf("[ events ] %zu matched (%zu near a frame's edge, %zu before a replan, %zu in crossfades (%zu of them walk <-> "
                "run pairs), %zu before the epoch); %zu character-frames out of view, %zu replanned twice in a frame; worst time %.2g s, place "
                "%.2g m (%.2g m in crossfades)\n",
                run.matched, run.nearEdge, run.beforeReplan, run.inCrossfade, run.paired, run.beforeEpoch, run.outOfView,
                run.replannedTwice, run.worstTime, run.worstPlace, run.worstPlaceInCrossfade);
    return run;
}

// 400 soldiers, 240 frames from 62 s (across the epoch at 64 s), GPU animation and culling.
TEST_F(GpuTest, GpuEventsEqualTheCrowdsEventsForTheCharactersInView) {
    test::RendererOptions options;
    options.method = skin::Method::Compute;
    const OrbitRun run = compareAlongAnOrbit(*context, options, 400, 240, 62.005);
    // Not trivial: many events, some characters out of view, some events fired by the segment a
    // replan inside the frame ended, some in crossfades, some before the epoch in the frame that
    // crosses it; few need the frame beside.
    EXPECT_GT(run.cpuTotal, 150u);
    EXPECT_GT(run.outOfView, 0u);
    EXPECT_GT(run.beforeReplan, 0u);
    EXPECT_GT(run.inCrossfade, 0u);
    EXPECT_GT(run.beforeEpoch, 0u);
    EXPECT_LE(run.nearEdge, run.cpuTotal / 50);
    EXPECT_LT(run.worstTime, kTimeTolerance);
    // Positions: the placement at the event's time on the joint's clip pose, against the CPU's whole
    // animation (1 mm; outside crossfades they differ by float rounding and the quadrature of the path).
    // In a crossfade the GPU takes the firing clip's pose alone (weight >= 1/2): within 10 cm.
    EXPECT_LT(run.worstPlace, 1e-3);
    EXPECT_LT(run.worstPlaceInCrossfade, 0.1);
}

// Walk <-> run crossfades commanded every 40 frames (docs/events.md#firing): the pairs of the walk's
// and the run's steps (points 0.1 and 0.08 of a cycle apart) fire once, where the phase meets the
// point blended by the weight, on the GPU as on the CPU.
TEST_F(GpuTest, GpuEventsEqualTheCrowdsEventsThroughWalkRunCrossfades) {
    test::RendererOptions options;
    options.method = skin::Method::Compute;
    const OrbitRun run = compareAlongAnOrbit(*context, options, 100, 120, 2.005, true);
    EXPECT_GT(run.paired, 20u);
    EXPECT_LE(run.nearEdge, run.cpuTotal / 50);
    EXPECT_LT(run.worstTime, kTimeTolerance);
    EXPECT_LT(run.worstPlace, 1e-3);
    // The GPU places a pair on the firing clip's pose at that clip's own point, while the pair fires
    // at the blended point, up to 0.1 cycles away: measured 12 cm from jointWorld's blended pose.
    EXPECT_LT(run.worstPlaceInCrossfade, 0.15);
}

// The same with the CPU animation path (the event pass uploads the segments itself) and CPU culling
// (its in-view words uploaded): 100 soldiers, 60 frames.
TEST_F(GpuTest, GpuEventsEqualTheCrowdsEventsWithCpuAnimationAndCulling) {
    test::RendererOptions options;
    options.method = skin::Method::Compute;
    options.animation = render::AnimationPath::Cpu;
    options.cull.mode = render::CullMode::Cpu;
    const OrbitRun run = compareAlongAnOrbit(*context, options, 100, 60, 10.0);
    EXPECT_GT(run.cpuTotal, 20u);
    EXPECT_GT(run.outOfView, 0u);
    EXPECT_LE(run.nearEdge, run.cpuTotal / 20);
    EXPECT_LT(run.worstTime, kTimeTolerance);
    EXPECT_LT(run.worstPlace, 1e-3);
}

// A buffer of 8 records in a frame where many more fire: exactly 8 written, each one of the CPU's
// events, and the rest counted as dropped.
TEST_F(GpuTest, FullEventBufferKeepsItsCapacityAndCountsTheRest) {
    const model::SkinnedModel soldier = soldierWithEvents();
    app::SceneOptions scene;
    scene.count = 100;
    scene.clip = "walk";
    crowd::Crowd crowd(soldier, test::buildCharacters(soldier, scene));
    test::RendererOptions options;
    options.size = {160, 90};
    options.method = skin::Method::Compute;
    options.shadows = false;
    options.cull.mode = render::CullMode::Off;  // everyone in view
    options.eventCapacity = 8;
    test::TestRenderer renderer(*context, crowd, options);
    renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 160.0f / 90.0f, 0.0f);
    renderer.renderFrame(1.0);
    renderer.renderFrame(2.0);  // a one-second window: each walker steps about twice
    renderer.finish();
    const GpuFrameEvents gpu = readEvents(*context, renderer);
    std::vector<std::uint32_t> everyone(crowd.size());
    for (std::uint32_t c = 0; c < crowd.size(); ++c) everyone[c] = c;
    std::vector<crowd::FiredEvent> cpu;
    crowd.events(everyone, 1.0, 2.0, cpu);
    ASSERT_GT(cpu.size(), 100u);
    EXPECT_EQ(gpu.header.capacity, 8u);
    EXPECT_EQ(gpu.header.count, 8u);
    EXPECT_EQ(gpu.header.dropped + gpu.header.count, cpu.size());
    ASSERT_EQ(gpu.records.size(), 8u);
    std::vector<bool> taken(cpu.size(), false);
    for (const gpu::EventRecord& r : gpu.records) {
        const double time = 2.0 - static_cast<double>(r.place.w);
        bool found = false;
        for (std::size_t i = 0; i < cpu.size() && !found; ++i)
            if (!taken[i] && cpu[i].character == r.ids.x && cpu[i].clip == r.ids.y && cpu[i].event == r.ids.z &&
                std::abs(cpu[i].time - time) < kTimeTolerance)
                taken[i] = found = true;
        EXPECT_TRUE(found) << "record of character " << r.ids.x << " is no event the CPU fired";
    }
}

}  // namespace

namespace {

// The capacity's bounds, through the public API (memoryNeeded checks settings as the constructor
// does): 0 and more than 4,000,000 records are refused in one line; with events off it is not read.
// The memory counts the buffer: 32 bytes a record more for a larger capacity.
TEST_F(GpuTest, EventCapacityOutOfRangeIsRefusedAndItsBufferCounted) {
    crowdgpu::GridLayout layout;
    layout.count = 16;
    const crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout);
    crowdgpu::RendererSettings settings;
    for (const std::uint32_t capacity : {0u, 4000001u}) {
        settings.eventCapacity = capacity;
        try {
            crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings);
            ADD_FAILURE() << "capacity " << capacity << " accepted";
        } catch (const crowdgpu::Error& error) {
            EXPECT_EQ(error.code(), crowdgpu::ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(error.what()).find("event capacity"), std::string::npos) << error.what();
        }
    }
    settings.events = false;
    const std::uint64_t off = crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings);
    settings.events = true;
    settings.eventCapacity = 1000;
    const std::uint64_t small = crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings);
    settings.eventCapacity = 2000;
    const std::uint64_t large = crowdgpu::memoryNeeded(context->physicalDevice, crowd, settings);
    EXPECT_GT(small, off);
    EXPECT_EQ(large - small, 1000u * sizeof(crowdgpu::GpuEvent));
}

}  // namespace
