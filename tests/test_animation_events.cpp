// Animation events (crowdgpu::Crowd::events, glTF extras): the same events for any frame rate, window
// split and thread, and the glTF field parsed or refused in one line.
#include <algorithm>
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"
#include "crowdgpu/model.hpp"
#include "gpu/error.h"
#include "support/gltf_builder.h"

namespace crowdgpu {
// Exact equality (found by vector's == through argument-dependent lookup).
bool operator==(const Event& a, const Event& b) {
    return a.character == b.character && a.clip == b.clip && a.event == b.event && a.time == b.time;
}
}  // namespace crowdgpu

namespace {

constexpr double kFrame = 1.0 / 60.0;

std::vector<std::uint32_t> everyone(const crowdgpu::Crowd& crowd) {
    std::vector<std::uint32_t> all(crowd.size());
    for (std::uint32_t c = 0; c < crowd.size(); ++c) all[c] = c;
    return all;
}

// Every event of the crowd over (0, end], advancing and asking in windows of `step` seconds; sorted
// by character, then time.
std::vector<crowdgpu::Event> eventsInSteps(crowdgpu::Crowd& crowd, double end, double step) {
    const std::vector<std::uint32_t> all = everyone(crowd);
    std::vector<crowdgpu::Event> result, window;
    crowd.advanceTo(0.0);
    for (std::uint64_t k = 0;; ++k) {
        const double from = static_cast<double>(k) * step, to = std::min(from + step, end);
        if (from >= end) break;
        crowd.advanceTo(to);
        crowd.events(all.data(), all.size(), from, to, window);
        result.insert(result.end(), window.begin(), window.end());
    }
    std::stable_sort(result.begin(), result.end(),
                     [](const crowdgpu::Event& a, const crowdgpu::Event& b) { return a.character < b.character; });
    return result;
}

// The soldier with events in its walk and run cycles (at a quarter and at 0.7 of each), set by hand as
// a glTF file's extras would set them.
crowdgpu::Model soldierWithEvents() {
    model::SkinnedModel m = crowdgpu::Model::soldier(1).data()->model;
    for (anim::Clip& clip : m.clips)
        if (clip.name == "walk" || clip.name == "run")
            clip.events = {{"step.left", 0.25f * clip.duration}, {"step.right", 0.7f * clip.duration}};
    return crowdgpu::Model(std::make_shared<const crowdgpu::detail::ModelData>(crowdgpu::detail::ModelData{m, {}}));
}

TEST(AnimationEvents, SameEventsAtAnyFrameRateWindowAndThread) {
    const crowdgpu::Model soldier = soldierWithEvents();
    crowdgpu::GridLayout layout;
    layout.count = 12;
    layout.seed = 9;
    for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::InPlace, crowdgpu::Behaviour::Mill}) {
        crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, behaviour);
        const std::vector<crowdgpu::Event> at60 = eventsInSteps(crowd, 20.0, kFrame);
        EXPECT_GT(at60.size(), 50u);  // some events to compare
        EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 1.0 / 24.0)) << crowdgpu::behaviourName(behaviour);
        EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 1.0 / 144.0)) << crowdgpu::behaviourName(behaviour);
        EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 0.25)) << crowdgpu::behaviourName(behaviour);
        if (behaviour == crowdgpu::Behaviour::InPlace) {
            // In place nothing replans: the whole window in one call.
            const std::vector<std::uint32_t> all = everyone(crowd);
            std::vector<crowdgpu::Event> once;
            crowd.advanceTo(20.0);
            crowd.events(all.data(), all.size(), 0.0, 20.0, once);
            EXPECT_TRUE(once == at60);
        }
        // Threads asking at once, each for some of the characters: the same events.
        crowd.advanceTo(0.0);
        crowd.advanceTo(3.0);
        const std::vector<std::uint32_t> all = everyone(crowd);
        std::vector<crowdgpu::Event> whole;
        crowd.events(all.data(), all.size(), 2.5, 3.0, whole);
        std::vector<std::vector<crowdgpu::Event>> parts(4);
        std::vector<std::thread> threads;
        for (std::size_t p = 0; p < parts.size(); ++p)
            threads.emplace_back([&, p] { crowd.events(all.data() + 3 * p, 3, 2.5, 3.0, parts[p]); });
        for (std::thread& t : threads) t.join();
        std::vector<crowdgpu::Event> joined;
        for (const auto& part : parts) joined.insert(joined.end(), part.begin(), part.end());
        EXPECT_TRUE(joined == whole);
    }
}

TEST(AnimationEvents, BadCharacterOrForgottenWindowIsInvalidArgument) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1);
    crowdgpu::GridLayout layout;
    layout.count = 2;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, crowdgpu::Behaviour::Mill);
    crowd.advanceTo(600.0);
    std::vector<crowdgpu::Event> out;
    const std::uint32_t missing = 2, first = 0;
    auto code = [&](auto&& call) {
        try {
            call();
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
            return e.code();
        }
        return static_cast<crowdgpu::ErrorCode>(0);
    };
    EXPECT_EQ(code([&] { crowd.events(&missing, 1, 599.0, 600.0, out); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { crowd.events(&first, 1, 0.0, 600.0, out); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { crowd.events(&first, 1, 600.0, 599.0, out); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { soldier.eventName(0, 1000); }), crowdgpu::ErrorCode::InvalidArgument);
}

TEST(AnimationEvents, GltfExtrasGiveClipEvents) {
    test::GltfBuilder b = test::stripCharacter();
    b.doc["animations"][0]["extras"] = {{"author", "kept out of the way"},
                                        {"events", {{{"name", "tock"}, {"time", 0.75}}, {{"name", "tick"}, {"time", 0}}}}};
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.clips.size(), 1u);
    ASSERT_EQ(m.clips[0].events.size(), 2u);
    EXPECT_EQ(m.clips[0].events[0].name, "tick");
    EXPECT_EQ(m.clips[0].events[0].time, 0.0f);
    EXPECT_EQ(m.clips[0].events[1].name, "tock");
    EXPECT_EQ(m.clips[0].events[1].time, 0.75f);
}

TEST(AnimationEvents, MalformedGltfEventsAreRefusedInOneLine) {
    const std::vector<std::pair<nlohmann::json, std::string>> cases = {
        {{{"events", {{"name", "x"}}}}, "animations[0].extras.events: expected an array"},
        {{{"events", {7}}}, "animations[0].extras.events[0]: expected an object"},
        {{{"events", {{{"time", 0.5}}}}}, "animations[0].extras.events[0].name"},
        {{{"events", {{{"name", "x"}, {"time", "soon"}}}}}, "animations[0].extras.events[0].time: expected a number"},
        {{{"events", {{{"name", "x"}, {"time", 2.5}}}}}, "animations[0].extras.events[0].time: 2.5"},
        {{{"events", {{{"name", "x"}, {"time", -0.1}}}}}, "outside the clip"},
    };
    for (const auto& [extras, mention] : cases) {
        test::GltfBuilder b = test::stripCharacter();
        b.doc["animations"][0]["extras"] = extras;
        try {
            test::loadText(b.gltf());
            ADD_FAILURE() << "accepted " << extras.dump();
        } catch (const gpu::Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind("test.gltf: ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_NE(message.find(mention), std::string::npos) << message;
        }
    }
}

}  // namespace
