// Animation events (crowdgpu::Crowd::events, glTF extras): the same events for any frame rate, window
// split and thread, and the glTF field parsed or refused in one line.
#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/crowdgpu.h"
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

// The crowd's events over 20 s are identical (exact doubles) stepped at 60, 24 and 144 Hz and in
// 0.25 s windows (in place: also in one call), and four threads asking for parts of the crowd at once
// give the one thread's list.
void expectSameEventsAtAnyFrameRateWindowAndThread(crowdgpu::Crowd& crowd, const std::string& what) {
    const std::vector<crowdgpu::Event> at60 = eventsInSteps(crowd, 20.0, kFrame);
    EXPECT_GT(at60.size(), 4u * crowd.size()) << what;  // some events to compare
    EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 1.0 / 24.0)) << what;
    EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 1.0 / 144.0)) << what;
    EXPECT_TRUE(at60 == eventsInSteps(crowd, 20.0, 0.25)) << what;
    const std::vector<std::uint32_t> all = everyone(crowd);
    if (what.find("in-place") != std::string::npos) {
        // In place nothing replans: the whole window in one call.
        std::vector<crowdgpu::Event> once;
        crowd.advanceTo(20.0);
        crowd.events(all.data(), all.size(), 0.0, 20.0, once);
        EXPECT_TRUE(once == at60) << what;
    }
    // Threads asking at once, each for a quarter of the characters: the same events.
    crowd.advanceTo(0.0);
    crowd.advanceTo(3.0);
    std::vector<crowdgpu::Event> whole;
    crowd.events(all.data(), all.size(), 2.5, 3.0, whole);
    const std::size_t quarter = all.size() / 4;
    std::vector<std::vector<crowdgpu::Event>> parts(4);
    std::vector<std::thread> threads;
    for (std::size_t p = 0; p < parts.size(); ++p)
        threads.emplace_back([&, p] {
            const std::size_t count = p + 1 == parts.size() ? all.size() - 3 * quarter : quarter;
            crowd.events(all.data() + quarter * p, count, 2.5, 3.0, parts[p]);
        });
    for (std::thread& t : threads) t.join();
    std::vector<crowdgpu::Event> joined;
    for (const auto& part : parts) joined.insert(joined.end(), part.begin(), part.end());
    EXPECT_TRUE(joined == whole) << what;
}

TEST(AnimationEvents, SameEventsAtAnyFrameRateWindowAndThread) {
    const crowdgpu::Model soldier = soldierWithEvents();
    crowdgpu::GridLayout layout;
    layout.count = 12;
    layout.seed = 9;
    for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::InPlace, crowdgpu::Behaviour::Mill}) {
        crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, behaviour);
        expectSameEventsAtAnyFrameRateWindowAndThread(crowd, crowdgpu::behaviourName(behaviour));
    }
}

TEST(AnimationEvents, BuiltInFootstepsAreTheSameAtAnyFrameRateWindowAndThread) {
    // Soldiers and horses of their own seeds, walking, running and galloping in place (random clips)
    // and milling (crossfades, replans), on a crowd seed that is not the default.
    const std::vector<crowdgpu::Model> models = {crowdgpu::Model::soldier(3), crowdgpu::Model::horse(5)};
    crowdgpu::GridLayout layout;
    layout.count = 16;
    layout.seed = 23;
    layout.randomClips = true;
    for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::InPlace, crowdgpu::Behaviour::Mill}) {
        crowdgpu::Crowd crowd = crowdgpu::Crowd::grid(models, layout, behaviour);
        expectSameEventsAtAnyFrameRateWindowAndThread(crowd, std::string("footsteps ") + crowdgpu::behaviourName(behaviour));
        // They are footsteps: every event the crowd fired is one.
        crowd.advanceTo(0.0);
        crowd.advanceTo(2.0);
        const std::vector<std::uint32_t> all = everyone(crowd);
        std::vector<crowdgpu::Event> fired;
        crowd.events(all.data(), all.size(), 1.0, 2.0, fired);
        for (const crowdgpu::Event& e : fired) {
            const crowdgpu::Model& m = models[crowd.character(e.character).model];
            EXPECT_EQ(m.eventName(e.clip, e.event), "footstep");
            EXPECT_GE(m.eventJoint(e.clip, e.event), 0);
        }
    }
}

TEST(AnimationEvents, CApiGivesTheCrowdsEventsAndRefusesTooSmallABuffer) {
    // The same milling crowd through C and C++: the same events, field for field.
    crowdgpu_model soldier = nullptr, horse = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(2, &soldier), CROWDGPU_OK);
    ASSERT_EQ(crowdgpu_model_horse(2, &horse), CROWDGPU_OK);
    const crowdgpu_model models[2] = {soldier, horse};
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(models, 2, 40, 7, CROWDGPU_MILL, &c), CROWDGPU_OK);
    crowdgpu::GridLayout layout;
    layout.count = 40;
    layout.seed = 7;
    crowdgpu::Crowd cpp = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(2), crowdgpu::Model::horse(2)}, layout,
                                                crowdgpu::Behaviour::Mill);
    const std::vector<std::uint32_t> all = everyone(cpp);
    std::vector<crowdgpu::Event> expected;
    std::vector<crowdgpu_event> got;
    std::size_t total = 0;
    for (int frame = 0; frame < 600; ++frame) {  // 20 s at 30 Hz
        const double t = frame / 30.0, next = (frame + 1) / 30.0;
        cpp.advanceTo(next);
        ASSERT_EQ(crowdgpu_crowd_advance_to(c, next), CROWDGPU_OK);
        cpp.events(all.data(), all.size(), t, next, expected);
        std::uint32_t count = 0;
        EXPECT_EQ(crowdgpu_crowd_events(c, all.data(), 40, t, next, nullptr, 0, &count),
                  expected.empty() ? CROWDGPU_OK : CROWDGPU_ERROR_INVALID_ARGUMENT);
        ASSERT_EQ(count, expected.size());
        got.assign(count + 1, crowdgpu_event{99, 99, 99, -1.0});
        ASSERT_EQ(crowdgpu_crowd_events(c, all.data(), 40, t, next, got.data(), count + 1, &count), CROWDGPU_OK);
        for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(got[i].character, expected[i].character);
            EXPECT_EQ(got[i].clip, expected[i].clip);
            EXPECT_EQ(got[i].event, expected[i].event);
            EXPECT_EQ(got[i].time, expected[i].time);
        }
        EXPECT_EQ(got[count].character, 99u);  // nothing past the events
        if (count > 1) {  // too small a buffer: the count, an error naming it, nothing written
            got.assign(count, crowdgpu_event{99, 99, 99, -1.0});
            std::uint32_t again = 0;
            EXPECT_EQ(crowdgpu_crowd_events(c, all.data(), 40, t, next, got.data(), count - 1, &again),
                      CROWDGPU_ERROR_INVALID_ARGUMENT);
            EXPECT_EQ(again, count);
            EXPECT_NE(std::string(crowdgpu_last_error()).find("room for " + std::to_string(count - 1)), std::string::npos);
            EXPECT_EQ(got[0].character, 99u);
        }
        total += count;
    }
    EXPECT_GT(total, 150u);
    const std::uint32_t missing = 40;
    std::uint32_t count = 0;
    crowdgpu_event one;
    EXPECT_EQ(crowdgpu_crowd_events(c, &missing, 1, 19.9, 20.0, &one, 1, &count), CROWDGPU_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(crowdgpu_last_error()).find("40"), std::string::npos) << crowdgpu_last_error();
    EXPECT_EQ(crowdgpu_crowd_events(c, all.data(), 40, 0.0, 20.0, nullptr, 0, &count), CROWDGPU_ERROR_INVALID_ARGUMENT)
        << "a window the milling crowd has forgotten";
    EXPECT_EQ(crowdgpu_crowd_events(c, nullptr, 1, 19.9, 20.0, &one, 1, &count), CROWDGPU_ERROR_INVALID_ARGUMENT);
    // The model's events through C are the model's.
    const crowdgpu::Model& model = cpp.models()[0];
    const auto walk = static_cast<std::uint32_t>(model.findClip("walk"));
    std::uint32_t steps = 0;
    ASSERT_EQ(crowdgpu_model_event_count(soldier, walk, &steps), CROWDGPU_OK);
    ASSERT_EQ(steps, model.eventCount(walk));
    for (std::uint32_t e = 0; e < steps; ++e) {
        const char* name = nullptr;
        float seconds = 0.0f;
        std::int32_t joint = -2;
        ASSERT_EQ(crowdgpu_model_event_name(soldier, walk, e, &name), CROWDGPU_OK);
        ASSERT_EQ(crowdgpu_model_event_time(soldier, walk, e, &seconds), CROWDGPU_OK);
        ASSERT_EQ(crowdgpu_model_event_joint(soldier, walk, e, &joint), CROWDGPU_OK);
        EXPECT_EQ(std::string(name), model.eventName(walk, e));
        EXPECT_EQ(seconds, model.eventTime(walk, e));
        EXPECT_EQ(joint, model.eventJoint(walk, e));
    }
    std::int32_t joint = 0;
    EXPECT_EQ(crowdgpu_model_event_joint(soldier, walk, steps, &joint), CROWDGPU_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(std::string(crowdgpu_last_error()).find('\n'), std::string::npos);
    EXPECT_EQ(joint, 0);
    EXPECT_EQ(crowdgpu_model_event_time(soldier, walk, 0, nullptr), CROWDGPU_ERROR_INVALID_ARGUMENT);
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
    crowdgpu_model_destroy(horse);
}

TEST(AnimationEvents, EveryFramesWindowIsAnsweredInALargeMillingCrowd) {
    // 10,000 milling soldiers: some characters replan twice within a frame (entering an episode whose
    // first segment lasts a few milliseconds). Every frame's window is still answered, and the events
    // are those of the same crowd stepped at 144 Hz; a joint inside such a window is known too.
    crowdgpu::GridLayout layout;
    layout.count = 10000;
    auto run = [&](double step, std::vector<crowdgpu::Event>& all) {
        crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout, crowdgpu::Behaviour::Mill);
        const std::vector<std::uint32_t> everybody = everyone(crowd);
        std::vector<crowdgpu::Event> window;
        crowd.advanceTo(30.0);
        std::uint32_t refused = 0;
        for (std::uint32_t k = 1; k * step <= 1.0 + 1e-9; ++k) {
            const double from = 30.0 + (k - 1) * step, to = 30.0 + k * step;
            crowd.advanceTo(to);
            try {
                crowd.events(everybody.data(), everybody.size(), from, to, window);
                float rows[12];
                for (const crowdgpu::Event& e : window) crowd.jointWorld(e.character, 0, from + 1e-6, rows);
            } catch (const crowdgpu::Error& e) {
                if (refused++ == 0) ADD_FAILURE() << step << " s steps: " << e.what();
                continue;
            }
            all.insert(all.end(), window.begin(), window.end());
        }
        EXPECT_EQ(refused, 0u) << step << " s steps";
        std::stable_sort(all.begin(), all.end(), [](const crowdgpu::Event& a, const crowdgpu::Event& b) { return a.character < b.character; });
    };
    std::vector<crowdgpu::Event> at60, at144;
    run(1.0 / 60.0, at60);
    run(1.0 / 144.0, at144);
    EXPECT_GT(at60.size(), 1000u);
    EXPECT_TRUE(at60 == at144);
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
    EXPECT_EQ(m.clips[0].events[0].joint, -1);  // no "joint": none
}

TEST(AnimationEvents, GltfEventJointIsTheSkeletonsJointOfThatName) {
    test::GltfBuilder b = test::stripCharacter();
    b.doc["animations"][0]["extras"] = {
        {"events", {{{"name", "tap"}, {"time", 0.5}, {"joint", "tip"}}, {{"name", "hum"}, {"time", 0.25}, {"joint", "root"}}}}};
    const model::SkinnedModel m = test::loadText(b.gltf());
    ASSERT_EQ(m.clips[0].events.size(), 2u);
    const std::vector<std::string>& names = m.skeleton.jointNames;
    ASSERT_GE(m.clips[0].events[0].joint, 0);
    ASSERT_GE(m.clips[0].events[1].joint, 0);
    EXPECT_EQ(names[static_cast<std::size_t>(m.clips[0].events[0].joint)], "root");  // hum, at 0.25 s
    EXPECT_EQ(names[static_cast<std::size_t>(m.clips[0].events[1].joint)], "tip");
    EXPECT_NE(m.clips[0].events[0].joint, m.clips[0].events[1].joint);
}

TEST(AnimationEvents, AnEmptyEventListIsAClipWithoutEvents) {
    test::GltfBuilder b = test::stripCharacter();
    b.doc["animations"][0]["extras"] = nlohmann::json::parse(R"({"events": []})");
    EXPECT_TRUE(test::loadText(b.gltf()).clips[0].events.empty());
}

TEST(AnimationEvents, MalformedGltfEventsAreRefusedInOneLine) {
    const auto J = [](const char* text) { return nlohmann::json::parse(text); };
    const std::vector<std::pair<nlohmann::json, std::string>> cases = {
        {{{"events", {{"name", "x"}}}}, "animations[0].extras.events: expected an array"},
        {{{"events", {7}}}, "animations[0].extras.events[0]: expected an object"},
        {{{"events", {{{"time", 0.5}}}}}, "animations[0].extras.events[0].name"},
        {{{"events", {{{"name", "x"}, {"time", "soon"}}}}}, "animations[0].extras.events[0].time: expected a number"},
        {{{"events", {{{"name", "x"}, {"time", 2.5}}}}}, "animations[0].extras.events[0].time: 2.5"},
        {{{"events", {{{"name", "x"}, {"time", -0.1}}}}}, "outside the clip"},
        {{{"events", {{{"name", "x"}, {"time", 0.1}, {"joint", "tail"}}}}},
         "animations[0].extras.events[0].joint: no joint named 'tail'"},
        {{{"events", {{{"name", "x"}, {"time", 0.1}, {"joint", 1}}}}}, "animations[0].extras.events[0].joint: expected"},
        {{{"events", {{{"name", "x"}, {"time", 0.1}, {"joint", "body"}}}}}, "no joint named 'body'"},  // a node, not a joint
        // tinygltf drops null, [] and {} from extras: each of these loaded silently as no event (issue 41).
        {J(R"({"events": null})"), "animations[0].extras.events: expected an array of {\"name\": string, \"time\": seconds}, found null"},
        {J(R"({"events": {}})"), "animations[0].extras.events: expected an array"},
        {J(R"({"events": [null]})"), "animations[0].extras.events[0]: expected an object {\"name\": string, \"time\": seconds}, found null"},
        {J(R"({"events": [{}]})"), "animations[0].extras.events[0].name: expected a non-empty string, found none"},
        {J(R"({"events": [[]]})"), "animations[0].extras.events[0]: expected an object"},
        {J(R"({"events": [{"name": "x", "time": 0.1}, null]})"), "animations[0].extras.events[1]: expected an object"},
        {J(R"({"events": [{"name": null, "time": 0.1}]})"), "animations[0].extras.events[0].name: expected a non-empty string, found null"},
        {J(R"({"events": [{"name": "x", "time": null}]})"), "animations[0].extras.events[0].time: expected a number of seconds, found null"},
        {J(R"({"events": [{"name": "x", "time": 0.1, "joint": {}}]})"),
         "animations[0].extras.events[0].joint: expected the name of a joint (a string), found an object"},
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
