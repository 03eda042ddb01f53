// Characters the host drives (crowd/driven.h, shaders/driven_keys.h, docs/host-driven.md), on the CPU:
// a path computed by hand, the gait by speed, feet that move at the ground speed, the delay and the
// extrapolation, late samples, events and joints from keys, and every refusal.
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "crowd/crowd.h"
#include "crowd/driven_rules.h"
#include "crowd/motion.h"
#include "crowdgpu/crowd.hpp"
#include "gpu/error.h"
#include "support/gpu_test.h"

namespace {

using test::soldier;

// One character driven from the host's memory, its samples given one at a time; its ring keeps
// `keys` of them (a query further back than the ring reaches is refused, or held at the oldest).
struct Driven {
    crowd::Crowd crowd;
    crowd::Handle handle;
    explicit Driven(std::uint32_t keys = 8) : crowd({&soldier()}, {}, {}, crowd::Capacity{{4}, keys}) {
        crowd::Character c;
        c.driven = crowd::Driven::HostSamples;
        c.props = 0;
        handle = crowd.spawn(c);
    }
    crowd::DriveResult sample(double time, float x, float z, float heading = std::numeric_limits<float>::quiet_NaN()) {
        const crowd::Handle h[1] = {handle};
        const double t[1] = {time};
        const float xs[1] = {x}, zs[1] = {z}, hs[1] = {heading};
        return crowd.drive({h, t, xs, zs, hs});
    }
};

// Where a driven character stands off its samples' path: its clips' own sway, the root motion that
// keeps their planted feet still less its straight stride (the model's data), weighted as the clips are
// and turned to the heading (crowd::Crowd::drivenState adds it; a few centimetres).
glm::vec2 clipSway(const crowd::Crowd& crowd, const crowd::MotionState& s) {
    const anim::ClipLibrary& library = crowd.library();
    const float cycle = s.phase - std::floor(s.phase);
    auto sway = [&](std::uint32_t clip) { return library.rootMotion(0, clip, cycle) - cycle * library.stride(0, clip); };
    return crowd::turnToWorld(glm::mix(sway(s.clipFrom), sway(s.clipTo), s.weight), s.heading);
}

// The path a driven character's root follows at `time`: its state less its clips' sway.
glm::vec2 pathAt(const crowd::Crowd& crowd, std::uint32_t slot, double time) {
    const crowd::MotionState s = crowd.stateAt(slot, time);
    return glm::vec2(s.position.x, s.position.z) - clipSway(crowd, s);
}

// The hand's path: east at 1.2 m/s for 2 s from (0, 0), then north (+z) at 1.2 m/s for 2 s.
glm::vec2 lPath(double t) {
    if (t <= 2.0) return {1.2f * static_cast<float>(t), 0.0f};
    return {2.4f, 1.2f * static_cast<float>(std::min(t, 4.0) - 2.0)};
}

TEST(Driven, ACharacterFollowsAHandComputedPathBehindItsSamplesByTheDelay) {
    Driven d(64);  // 2.56 s of 25 Hz samples: the turn stays in the ring to the end
    d.crowd.setDrivenTiming({0.2, 0.5});
    // 25 Hz samples, as a simulation would send them, each frame's before its frame is drawn.
    for (int frame = 0; frame <= 4 * 60; ++frame) {
        const double time = frame / 60.0;
        for (double s = std::floor((time - 1.0 / 60.0) * 25.0 + 1.0) / 25.0; s <= time + 1e-9; s += 1.0 / 25.0)
            if (s >= 0.0) d.sample(s, lPath(s).x, lPath(s).y);
        d.crowd.advanceTo(time);
        if (time < 0.2) continue;
        // Drawn at time - delay, between the samples around it: the path itself (it is straight between them).
        const glm::vec2 path = pathAt(d.crowd, d.handle.slot, time), expected = lPath(time - 0.2);
        EXPECT_NEAR(path.x, expected.x, 2e-4f) << time;
        EXPECT_NEAR(path.y, expected.y, 2e-4f) << time;
        const crowd::MotionState state = d.crowd.stateAt(d.handle.slot, time);
        EXPECT_LT(glm::length(glm::vec2(state.position.x, state.position.z) - expected), 0.10f) << "sways by centimetres";
    }
    // Walking east then north: the body faces +x (pi/2), then turns to +z (0) at most 4 rad/s.
    EXPECT_NEAR(d.crowd.stateAt(d.handle.slot, 2.1).heading, std::numbers::pi_v<float> / 2.0f, 1e-3f);
    EXPECT_NEAR(d.crowd.stateAt(d.handle.slot, 3.5).heading, 0.0f, 1e-3f);
    const float turning = d.crowd.stateAt(d.handle.slot, 2.2 + 0.2).heading;  // 0.2 s into the turn
    EXPECT_NEAR(turning, std::numbers::pi_v<float> / 2.0f - 4.0f * 0.2f, 0.05f) << "turns at the bounded rate";
}

TEST(Driven, TheGaitFollowsTheSpeedAndTheFeetMoveAtTheGroundSpeed) {
    const crowd::Gaits& gaits = [] {
        static crowd::Crowd c({&soldier()}, {});
        return c.gaits(0);
    }();
    ASSERT_NE(gaits.walk, crowd::Gaits::kNone);
    ASSERT_NE(gaits.run, crowd::Gaits::kNone);
    ASSERT_NE(gaits.stand, crowd::Gaits::kNone);
    for (const float speed : {0.02f, 1.2f, 5.0f}) {
        Driven d(64);
        const crowd::GaitBands bands = d.crowd.gaitBands(0);
        for (int k = 0; k <= 80; ++k) d.sample(k * 0.04, speed * k * 0.04f, 0.0f);  // to 3.2 s
        d.crowd.advanceTo(3.0);
        const crowd::MotionState state = d.crowd.stateAt(d.handle.slot, 3.0);
        const std::uint32_t expected = speed < bands.walkFrom ? gaits.stand : speed < bands.runFrom ? gaits.walk : gaits.run;
        EXPECT_EQ(state.weight < 0.5f ? state.clipFrom : state.clipTo, static_cast<std::uint32_t>(expected)) << speed;
        if (speed < bands.walkFrom) continue;
        // Steady at one gait: a cycle lasts exactly the time its stride takes at this speed.
        const float stride = d.crowd.drivenModels()[0].cycles[expected == static_cast<std::uint32_t>(gaits.walk) ? 1 : 2];
        const float before = d.crowd.stateAt(d.handle.slot, 2.5).phase, after = d.crowd.stateAt(d.handle.slot, 3.0).phase;
        float cycles = after - before;
        cycles -= std::floor(cycles);  // within one wrap of the key phase's fraction
        const float expectedCycles = std::fmod(speed * 0.5f / stride, 1.0f);
        EXPECT_NEAR(cycles, expectedCycles, 1e-3f) << speed;
    }
}

TEST(Driven, PastItsLastSampleItGoesOnForTheExtrapolationThenComesToRest) {
    Driven d;
    d.crowd.setDrivenTiming({0.1, 0.5});
    for (int k = 0; k <= 50; ++k) d.sample(k * 0.04, 1.0f * k * 0.04f, 0.0f);  // 1 m/s east for 2 s
    d.crowd.advanceTo(2.0);
    // The last sample (2 s, x = 2) is drawn at 2.1 s; it goes on at 1 m/s until 2.6 s, then stops.
    EXPECT_NEAR(pathAt(d.crowd, d.handle.slot, 2.35).x, 2.25f, 1e-4f);
    EXPECT_NEAR(pathAt(d.crowd, d.handle.slot, 2.6).x, 2.5f, 1e-4f);
    EXPECT_NEAR(pathAt(d.crowd, d.handle.slot, 9.0).x, 2.5f, 1e-4f);
    const crowd::MotionState rest = d.crowd.stateAt(d.handle.slot, 9.0);
    EXPECT_EQ(rest.weight < 0.5f ? rest.clipFrom : rest.clipTo, static_cast<std::uint32_t>(d.crowd.gaits(0).stand));
    // A sample arriving late corrects it at once.
    d.sample(2.04, 2.0f, 0.1f);
    EXPECT_NEAR(pathAt(d.crowd, d.handle.slot, 2.14).y, 0.1f, 1e-4f);
}

TEST(Driven, ASampleNoLaterThanTheNewestIsIgnoredAndCounted) {
    Driven d;
    EXPECT_EQ(d.sample(1.0, 0.0f, 0.0f).applied, 1u);
    EXPECT_EQ(d.sample(1.5, 1.0f, 0.0f).applied, 1u);
    const crowd::DriveResult late = d.sample(1.2, 5.0f, 5.0f);
    EXPECT_EQ(late.applied, 0u);
    EXPECT_EQ(late.late, 1u);
    EXPECT_EQ(d.sample(1.5, 5.0f, 5.0f).late, 1u) << "the same time again";
    EXPECT_EQ(d.crowd.drivenKeys().count(d.handle.slot), 2u);
}

TEST(Driven, SeveralSamplesOfACharacterInOneBatchApplyInOrder) {
    Driven d;
    const crowd::Handle h[3] = {d.handle, d.handle, d.handle};
    const double t[3] = {0.0, 0.5, 1.0};
    const float x[3] = {0.0f, 0.5f, 1.0f}, z[3] = {0.0f, 0.0f, 0.0f};
    const crowd::DriveResult r = d.crowd.drive({h, t, x, z, {}});
    EXPECT_EQ(r.applied, 3u);
    EXPECT_NEAR(pathAt(d.crowd, d.handle.slot, 0.75 + 0.1).x, 0.75f, 1e-5f);
}

TEST(Driven, ABadBatchIsRefusedWholeNamingTheSampleAndItsCharacter) {
    Driven d;
    crowd::Character other;
    other.driven = crowd::Driven::HostSamples;
    const crowd::Handle second = d.crowd.spawn(other);
    auto refused = [&](std::vector<crowd::Handle> h, std::vector<double> t, std::vector<float> x, const std::string& word) {
        std::vector<float> z(x.size(), 0.0f);
        try {
            d.crowd.drive({h, t, x, z, {}});
            ADD_FAILURE() << "accepted: " << word;
        } catch (const gpu::Error& e) {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
        EXPECT_EQ(d.crowd.drivenKeys().empty() ? 0u : d.crowd.drivenKeys().count(d.handle.slot), 0u) << "nothing applied";
    };
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    refused({d.handle, second}, {0.0, nan}, {0.0f, 0.0f}, "sample 1 (character " + std::to_string(second.slot) + ")");
    refused({d.handle, second}, {0.0, inf}, {0.0f, 0.0f}, "finite");
    refused({d.handle, second}, {0.0, 0.0}, {0.0f, std::numeric_limits<float>::infinity()}, "finite");
    refused({d.handle, {second.slot, second.generation + 1}}, {0.0, 0.0}, {0.0f, 0.0f}, "never made");
    refused({d.handle, {77, 1}}, {0.0, 0.0}, {0.0f, 0.0f}, "no such slot");
    refused({d.handle, second}, {0.0}, {0.0f, 0.0f}, "differ in length");
    d.crowd.remove(second);
    refused({d.handle, second}, {0.0, 0.0}, {0.0f, 0.0f}, "removed");
    // A character driven by a device buffer takes no host samples, and the CPU knows none of its motion.
    crowd::Character device;
    device.driven = crowd::Driven::DeviceSamples;
    const crowd::Handle gpuDriven = d.crowd.spawn(device);
    refused({d.handle, gpuDriven}, {0.0, 0.0}, {0.0f, 0.0f}, "device buffer");
    try {
        d.crowd.jointWorld(gpuDriven.slot, 0, 0.0);
        ADD_FAILURE() << "a device-driven character's joint on the CPU";
    } catch (const gpu::Error& e) {
        EXPECT_EQ(e.kind(), gpu::ErrorKind::Unsupported) << e.what();
    }
    // A crowd made without driven keys drives no one.
    crowd::Crowd none({&soldier()}, {crowd::Character{}}, {}, crowd::Capacity{{}, 0});
    const crowd::Handle h[1] = {{0, 1}};
    const double t[1] = {0.0};
    const float x[1] = {0.0f};
    try {
        none.drive({h, t, x, x, {}});
        ADD_FAILURE() << "driven without keys";
    } catch (const gpu::Error& e) {
        EXPECT_NE(std::string(e.what()).find("drivenKeys"), std::string::npos) << e.what();
    }
}

TEST(Driven, EventsAndJointsOfADrivenCharacterFollowItsKeys) {
    Driven d(64);
    for (int k = 0; k <= 80; ++k) d.sample(k * 0.04, 1.3f * k * 0.04f, 0.0f);  // to 3.2 s: the ring holds 0.64 s on
    d.crowd.advanceTo(3.0);
    // Footsteps: a window in one call gives what the same window split over frames gives.
    std::vector<crowd::FiredEvent> whole, split, frame;
    const std::vector<std::uint32_t> who = {d.handle.slot};
    d.crowd.events(who, 1.0, 3.0, whole);
    for (int f = 0; f < 120; ++f) {
        frame.clear();  // the crowd appends
        d.crowd.events(who, 1.0 + f / 60.0, 1.0 + (f + 1) / 60.0, frame);
        split.insert(split.end(), frame.begin(), frame.end());
    }
    // Before the oldest key the ring keeps (0.64 s, drawn 0.1 s later): refused, not made up.
    EXPECT_THROW(d.crowd.events(who, 0.5, 1.0, frame), gpu::Error);
    ASSERT_EQ(whole.size(), split.size());
    for (std::size_t i = 0; i < whole.size(); ++i) EXPECT_NEAR(whole[i].time, split[i].time, 1e-9);
    // Walking at 1.3 m/s, a footstep of each foot every cycle.
    const float stride = d.crowd.drivenModels()[0].cycles.y;
    const double cycles = 1.3 * 2.0 / stride;
    EXPECT_NEAR(static_cast<double>(whole.size()), 2.0 * cycles, 2.5);
    // At an event's time its joint is on the ground, where the event says (feet move at the ground speed).
    const crowd::FiredEvent& e = whole.front();
    const std::int32_t joint = soldier().clips[e.clip].events[e.event].joint;
    ASSERT_GE(joint, 0);
    const anim::Affine at = d.crowd.jointWorld(d.handle.slot, static_cast<std::uint32_t>(joint), e.time);
    const anim::Affine later = d.crowd.jointWorld(d.handle.slot, static_cast<std::uint32_t>(joint), e.time + 0.05);
    EXPECT_LT(std::abs(at.row0.w - later.row0.w), 0.03f) << "a planted foot barely slides";
}

TEST(Driven, ThePublicApiDrivesABatchAndRefusesMissingArrays) {
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {2};
    crowdgpu::Character c;
    c.motion = crowdgpu::MotionSource::HostSamples;
    {
        // By default a crowd keeps keys only when some first character is driven: this one spawns them later.
        crowdgpu::Crowd undeclared({crowdgpu::Model::soldier(1)}, {}, crowdgpu::Behaviour::InPlace, 1, capacity);
        try {
            undeclared.spawn(c);
            ADD_FAILURE() << "a driven character in a crowd without driven keys";
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(e.what()).find("drivenKeys"), std::string::npos) << e.what();
        }
        EXPECT_EQ(undeclared.liveCount(), 0u);
    }
    capacity.drivenKeys = crowdgpu::kDrivenKeys;
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, {}, crowdgpu::Behaviour::InPlace, 1, capacity);
    const crowdgpu::CharacterHandle a = crowd.spawn(c), b = crowd.spawn(c);
    const crowdgpu::CharacterHandle who[2] = {a, b};
    const double times[2] = {0.5, 0.5};
    const float x[2] = {1.0f, 2.0f}, z[2] = {3.0f, 4.0f};
    const crowdgpu::DriveResult r = crowd.drive({who, times, x, z, nullptr, 2});
    EXPECT_EQ(r.applied, 2u);
    crowd.advanceTo(1.0);
    EXPECT_FLOAT_EQ(crowd.stateAt(b.slot, 1.0).position[0], 2.0f);
    EXPECT_FLOAT_EQ(crowd.stateAt(b.slot, 1.0).position[2], 4.0f);
    try {
        crowd.drive({who, nullptr, x, z, nullptr, 2});
        ADD_FAILURE() << "no times";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
    }
    crowdgpu::GaitSettings gaits = crowd.gaitSettings(0);
    gaits.runFrom = gaits.walkFrom;
    EXPECT_THROW(crowd.setGaitSettings(0, gaits), crowdgpu::Error);
    EXPECT_THROW(crowd.setDrivenTiming({-1.0, 0.5}), crowdgpu::Error);
}

}  // namespace
