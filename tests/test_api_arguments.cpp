// The public API checks its arguments at the door (issue 41): non-finite or huge times, positions,
// speeds, phases, headings, scales, tints, rates and fades, enum values, null physical devices and
// formats are refused with InvalidArgument (or Unsupported) in one line naming the argument, in C++ and
// through the C API, before anything changes; the inner code turns no non-finite value into an index;
// counting events costs no storage and no call keeps a large scratch list afterwards.
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <malloc.h>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "anim/root_motion.h"
#include "anim/sampling_job.h"
#include "crowdgpu/crowdgpu.h"
#include "crowdgpu/renderer.hpp"
#include "support/gpu_test.h"

using test::GpuTest;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The error a call throws: its code (0 when it throws none), and its message checked to be one line
// that mentions `words`.
crowdgpu::ErrorCode refusal(const std::string& words, const std::function<void()>& call) {
    try {
        call();
    } catch (const crowdgpu::Error& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find(words), std::string::npos) << "'" << message << "' does not mention '" << words << "'";
        return error.code();
    }
    ADD_FAILURE() << "accepted: " << words;
    return static_cast<crowdgpu::ErrorCode>(0);
}

#define EXPECT_REFUSED(words, call) EXPECT_EQ(refusal(words, [&] { call; }), crowdgpu::ErrorCode::InvalidArgument)

crowdgpu::Crowd walkingCrowd(crowdgpu::Behaviour behaviour, std::uint32_t count = 16) {
    crowdgpu::GridLayout layout;
    layout.count = count;
    return crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout, behaviour);
}

bool finite(const float* values, int count) {
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

// The C API's last call: its result and a message that mentions `words`.
void expectCRefused(crowdgpu_result result, const std::string& words) {
    EXPECT_EQ(result, CROWDGPU_ERROR_INVALID_ARGUMENT) << words;
    const std::string message = crowdgpu_last_error();
    EXPECT_NE(message.find(words), std::string::npos) << "'" << message << "' does not mention '" << words << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace

// Before: on a marching or milling crowd, advanceTo(inf), jointWorld at inf or 1e300 and a NaN
// window each crashed (SIGSEGV in anim::rootMotionAt, a NaN made an index) or ran forever.
TEST(ApiArguments, NonFiniteAndHugeTimesAreRefusedOnWalkingCrowdsInOneLine) {
    for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::March, crowdgpu::Behaviour::Mill}) {
        crowdgpu::Crowd crowd = walkingCrowd(behaviour);
        crowd.advanceTo(10.0);
        float rows[12];
        std::vector<crowdgpu::Event> events;
        std::vector<float> palettes;
        const std::uint32_t first = 0;
        for (const double bad : {kInf, -kInf, kNan, 1e300, -1e300, crowdgpu::kLargestTime * 1.000001}) {
            EXPECT_REFUSED("advanceTo: time", crowd.advanceTo(bad));
            EXPECT_REFUSED("jointWorld: time", crowd.jointWorld(0, 0, bad, rows));
            EXPECT_REFUSED("stateAt: time", crowd.stateAt(0, bad));
            EXPECT_REFUSED("computePalettes: time", crowd.computePalettes(bad, palettes, false));
            EXPECT_REFUSED("events: to", crowd.events(&first, 1, 10.0, bad, events));
            EXPECT_REFUSED("events: from", crowd.events(&first, 1, bad, 10.0, events));
            EXPECT_REFUSED("moveTo: at", crowd.moveTo(0, 1.0f, 1.0f, bad));
            EXPECT_REFUSED("play: at", crowd.play(0, 0, bad));
        }
        // Named with its value, as a person writes it.
        EXPECT_REFUSED("advanceTo: time: inf is not a finite number", crowd.advanceTo(kInf));
        EXPECT_REFUSED("1e+300 s is outside -1e+10 s .. 1e+10 s", crowd.advanceTo(1e300));
        // The crowd is as it was, and reaches the largest time accepted.
        crowd.jointWorld(3, 0, 10.0, rows);
        EXPECT_TRUE(finite(rows, 12));
        crowd.advanceTo(crowdgpu::kLargestTime);
        crowd.jointWorld(3, 0, crowdgpu::kLargestTime, rows);
        EXPECT_TRUE(finite(rows, 12));
    }
    // The same through the C API, which calls the C++ checks.
    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd crowd = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 16, 1, CROWDGPU_MILL, &crowd), CROWDGPU_OK);
    float rows[12];
    expectCRefused(crowdgpu_crowd_advance_to(crowd, kInf), "advanceTo: time");
    expectCRefused(crowdgpu_crowd_joint_world(crowd, 0, 0, kInf, rows), "jointWorld: time");
    expectCRefused(crowdgpu_crowd_joint_world(crowd, 0, 0, 1e300, rows), "jointWorld: time");
    expectCRefused(crowdgpu_crowd_move_to(crowd, 0, 1.0f, 1.0f, kNan), "moveTo: at");
    expectCRefused(crowdgpu_crowd_play(crowd, 0, 0, kNan, 0.3f), "play: at");
    EXPECT_EQ(crowdgpu_crowd_advance_to(crowd, 30.0), CROWDGPU_OK) << crowdgpu_last_error();
    EXPECT_EQ(crowdgpu_crowd_joint_world(crowd, 0, 0, 30.0, rows), CROWDGPU_OK);
    EXPECT_TRUE(finite(rows, 12));
    crowdgpu_crowd_destroy(crowd);
    crowdgpu_model_destroy(soldier);
}

// Before: accepted with OK, and a NaN or infinite phase crashed the next advance of a walking crowd
// (the rest reached the pose as NaN matrices).
TEST(ApiArguments, CharactersWithNonFiniteOrOutOfRangeValuesAreRefusedWhereverTheyEnter) {
    const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
    struct Case {
        std::function<void(crowdgpu::Character&)> spoil;
        std::string field;
    };
    const std::vector<Case> cases = {
        {[&](crowdgpu::Character& c) { c.phase = nan; }, "phase"},
        {[&](crowdgpu::Character& c) { c.phase = inf; }, "phase"},
        {[&](crowdgpu::Character& c) { c.speed = nan; }, "speed"},
        {[&](crowdgpu::Character& c) { c.speed = -1.0f; }, "speed"},
        {[&](crowdgpu::Character& c) { c.speed = 1e30f; }, "speed"},
        {[&](crowdgpu::Character& c) { c.position[0] = nan; }, "position[0]"},
        {[&](crowdgpu::Character& c) { c.position[2] = inf; }, "position[2]"},
        {[&](crowdgpu::Character& c) { c.position[1] = 1e30f; }, "position[1]"},
        {[&](crowdgpu::Character& c) { c.heading = nan; }, "heading"},
        {[&](crowdgpu::Character& c) { c.scale = 0.0f; }, "scale"},
        {[&](crowdgpu::Character& c) { c.scale = inf; }, "scale"},
        {[&](crowdgpu::Character& c) { c.tint[1] = nan; }, "tint[1]"},
        {[&](crowdgpu::Character& c) { c.tint[2] = -1.0f; }, "tint[2]"},
    };
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::Mill, 4);
    for (const Case& bad : cases) {
        crowdgpu::Character c;
        bad.spoil(c);
        EXPECT_REFUSED("spawn: the character's " + bad.field, crowd.spawn(c));
        std::vector<crowdgpu::Character> characters(3);
        bad.spoil(characters[2]);
        EXPECT_REFUSED("Crowd: character 2's " + bad.field,
                       crowdgpu::Crowd({crowdgpu::Model::soldier(1)}, characters, crowdgpu::Behaviour::Mill));
    }
    EXPECT_EQ(crowd.size(), 4u);
    crowd.advanceTo(20.0);
    float rows[12];
    crowd.jointWorld(3, 0, 20.0, rows);
    EXPECT_TRUE(finite(rows, 12));

    // In C: a NaN phase spawned into a milling crowd, then advanced, was a SIGSEGV.
    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 4, 1, CROWDGPU_MILL, &c), CROWDGPU_OK);
    crowdgpu_character spawned{};
    spawned.speed = spawned.scale = 1.0f;
    spawned.tint[0] = spawned.tint[1] = spawned.tint[2] = 1.0f;
    spawned.phase = nan;
    expectCRefused(crowdgpu_crowd_spawn(c, &spawned, nullptr), "phase");
    spawned.phase = 0.0f, spawned.position[0] = inf;
    expectCRefused(crowdgpu_crowd_spawn(c, &spawned, nullptr), "position[0]");
    EXPECT_EQ(crowdgpu_crowd_size(c), 4u);
    EXPECT_EQ(crowdgpu_crowd_advance_to(c, 20.0), CROWDGPU_OK);
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
}

TEST(ApiArguments, GridLayoutValuesAreChecked) {
    const std::vector<crowdgpu::Model> two = {crowdgpu::Model::soldier(1), crowdgpu::Model::horse(1)};
    auto grid = [&](const std::function<void(crowdgpu::GridLayout&)>& spoil) {
        crowdgpu::GridLayout layout;
        layout.count = 8;
        spoil(layout);
        return crowdgpu::Crowd::grid(two, layout);
    };
    EXPECT_REFUSED("scaleVariation", grid([](crowdgpu::GridLayout& l) { l.scaleVariation = std::nanf(""); }));
    EXPECT_REFUSED("scaleVariation", grid([](crowdgpu::GridLayout& l) { l.scaleVariation = 1.0f; }));
    EXPECT_REFUSED("tintVariation", grid([](crowdgpu::GridLayout& l) { l.tintVariation = -0.5f; }));
    EXPECT_REFUSED("weights[1]", grid([](crowdgpu::GridLayout& l) { l.weights = {1.0f, std::nanf("")}; }));
    EXPECT_REFUSED("weights are all 0", grid([](crowdgpu::GridLayout& l) { l.weights = {0.0f, 0.0f}; }));
    EXPECT_REFUSED("scales[0]", grid([](crowdgpu::GridLayout& l) { l.scales = {0.0f}; }));
    EXPECT_REFUSED("scales[1]", grid([](crowdgpu::GridLayout& l) { l.scales = {1.0f, INFINITY}; }));
    EXPECT_REFUSED("clips[0]", grid([](crowdgpu::GridLayout& l) { l.clips = {-2}; }));
    EXPECT_EQ(grid([](crowdgpu::GridLayout& l) { l.scaleVariation = 0.5f, l.weights = {0.0f, 1.0f}; }).size(), 8u);
}

TEST(ApiArguments, CommandsRefuseNonFiniteTargetsFadesAndRatesAndChangeNothing) {
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::InPlace, 2);
    crowd.advanceTo(1.0);
    const crowdgpu::CharacterState before = crowd.stateAt(0, 5.0);
    const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
    EXPECT_REFUSED("moveTo: x", crowd.moveTo(0, nan, 1.0f, 2.0));
    EXPECT_REFUSED("moveTo: z", crowd.moveTo(0, 1.0f, -inf, 2.0));
    EXPECT_REFUSED("moveTo: x", crowd.moveTo(0, 1e7f, 1.0f, 2.0));
    EXPECT_REFUSED("moveTo: rate", crowd.moveTo(0, 1.0f, 1.0f, 2.0, -1, nan));
    EXPECT_REFUSED("moveTo: rate", crowd.moveTo(0, 1.0f, 1.0f, 2.0, -1, 0.0f));
    EXPECT_REFUSED("play: fade", crowd.play(0, 0, 2.0, nan));
    EXPECT_REFUSED("play: fade", crowd.play(0, 0, 2.0, -0.5f));
    EXPECT_REFUSED("play: rate", crowd.play(0, 0, 2.0, 0.3f, inf));
    crowd.advanceTo(5.0);
    const crowdgpu::CharacterState after = crowd.stateAt(0, 5.0);
    EXPECT_EQ(std::memcmp(&before, &after, sizeof before), 0) << "a refused command changed the character";
}

// The inner functions that turn a float into an index are safe on their own: a NaN or infinite phase
// reads the first sample instead of anim::rootMotionAt's samples[INT_MIN] (the SIGSEGV), and a NaN
// time holds the first key instead of reading past the last.
TEST(ApiArguments, InnerFunctionsTurnNoNonFiniteValueIntoAnIndex) {
    std::array<glm::vec2, ROOT_MOTION_SAMPLES + 1> samples{};
    for (int i = 0; i <= ROOT_MOTION_SAMPLES; ++i) samples[static_cast<std::size_t>(i)] = glm::vec2(0.0f, 0.01f * i);
    for (const float phase : {std::nanf(""), INFINITY, -INFINITY}) {
        const glm::vec2 at = anim::rootMotionAt(samples.data(), phase);
        EXPECT_FALSE(std::isfinite(at.y)) << phase;
    }
    EXPECT_FLOAT_EQ(anim::rootMotionAt(samples.data(), 1.5f).y, 0.64f + 0.32f);
    const float times[3] = {0.0f, 0.5f, 1.0f};
    std::uint16_t cursor = 1;
    EXPECT_EQ(anim::findKeysFromCursor(times, 3, std::nanf(""), cursor).key, 0u);
    EXPECT_EQ(anim::findKeysFromCursor(times, 3, 0.75f, cursor).key, 1u);
}

// Before: Behaviour 99 silently made an in-place crowd.
TEST(ApiArguments, ABehaviourOutsideTheEnumIsRefused) {
    crowdgpu::GridLayout layout;
    layout.count = 4;
    EXPECT_REFUSED("behaviour 99 is not in-place (0), march (1) or mill (2)",
                   crowdgpu::Crowd::grid({crowdgpu::Model::soldier(1)}, layout, static_cast<crowdgpu::Behaviour>(99)));
    EXPECT_REFUSED("behaviour -1", crowdgpu::Crowd({crowdgpu::Model::soldier(1)}, {crowdgpu::Character{}},
                                                   static_cast<crowdgpu::Behaviour>(-1)));
}

// Before: memoryNeeded(VK_NULL_HANDLE, ...) was a SIGSEGV (in C too); the other queries taking a
// physical device read through it as well.
TEST(ApiArguments, ANullPhysicalDeviceIsRefusedByEveryQuery) {
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::InPlace, 4);
    EXPECT_REFUSED("memoryNeeded: no physical device", crowdgpu::memoryNeeded(VK_NULL_HANDLE, crowd, {}));
    EXPECT_REFUSED("checkDeviceLimits: no physical device", crowdgpu::checkDeviceLimits(VK_NULL_HANDLE, crowd, {}));
    EXPECT_REFUSED("viewportProblem: no physical device", crowdgpu::viewportProblem(VK_NULL_HANDLE, {}, {64, 64}));
    EXPECT_EQ(crowdgpu::checkPhysicalDevice(VK_NULL_HANDLE), "no physical device given");

    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 4, 1, CROWDGPU_IN_PLACE, &c), CROWDGPU_OK);
    crowdgpu_renderer_settings settings;
    crowdgpu_renderer_settings_default(&settings);
    EXPECT_EQ(crowdgpu_memory_needed(VK_NULL_HANDLE, c, &settings), 0u);
    EXPECT_NE(std::string(crowdgpu_last_error()).find("memoryNeeded: no physical device"), std::string::npos)
        << crowdgpu_last_error();
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
}

namespace {

// Bytes malloc holds for the program now (0 where a sanitizer's allocator replaces glibc's).
std::size_t heapInUse() { return mallinfo2().uordblks; }

// The growth of this process's peak resident memory over `call`, in MiB (the kernel's high-water mark,
// reset first through /proc/self/clear_refs).
double peakGrowthMiB(const std::function<void()>& call) {
    auto read = [](const char* field) {
        std::ifstream status("/proc/self/status");
        for (std::string line; std::getline(status, line);)
            if (line.rfind(field, 0) == 0) return std::stod(line.substr(std::strlen(field))) / 1024.0;
        return 0.0;
    };
    std::ofstream("/proc/self/clear_refs") << "5";
    const double before = read("VmRSS:");
    call();
    return read("VmHWM:") - before;
}

}  // namespace

// Before: crowdgpu_crowd_events(c, ids, n, 0, T, NULL, 0, &count), "the count alone", built every event
// first (348 MB at T = 1e6 for 16 soldiers, unbounded at 1e20 or inf) and both thread-local lists kept
// their capacity. Now a count stores nothing, a list takes what its capacity allows, a window is at
// most kLargestEventWindow long, and no scratch list stays large after a call.
TEST(ApiArguments, CountingEventsStoresNothingAndNoCallKeepsALargeList) {
    // 2,000 soldiers walking in place for an hour: about 13 million footsteps, 300 MiB as a list.
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::InPlace, 2000);
    crowd.advanceTo(0.0);
    std::vector<std::uint32_t> everyone(crowd.size());
    for (std::uint32_t c = 0; c < crowd.size(); ++c) everyone[c] = c;
    std::vector<crowdgpu::Event> list;
    std::uint64_t counted = 0;
    const double countPeak = peakGrowthMiB([&] {
        counted = crowd.events(everyone.data(), everyone.size(), 0.0, crowdgpu::kLargestEventWindow, list, 0);
    });
    EXPECT_GT(counted, 10'000'000u);
    EXPECT_TRUE(list.empty());
    EXPECT_LT(countPeak, 16.0) << "MiB to count " << counted << " events";

    // In C, the count alone (out NULL, capacity 0): the count, INVALID_ARGUMENT (no room), nothing kept.
    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 2000, 1, CROWDGPU_IN_PLACE, &c), CROWDGPU_OK);
    ASSERT_EQ(crowdgpu_crowd_advance_to(c, 0.0), CROWDGPU_OK);
    std::uint32_t cCount = 0;
    const std::size_t heapBefore = heapInUse();
    const double cPeak = peakGrowthMiB([&] {
        EXPECT_EQ(crowdgpu_crowd_events(c, everyone.data(), 2000, 0.0, crowdgpu::kLargestEventWindow, nullptr, 0, &cCount),
                  CROWDGPU_ERROR_INVALID_ARGUMENT);
    });
    EXPECT_EQ(cCount, counted);
    EXPECT_LT(cPeak, 16.0) << "MiB for the C API to count " << cCount << " events";
    EXPECT_LT(heapInUse(), heapBefore + (4u << 20)) << "bytes kept after counting";

    // A list as large as asked: given, then released (a frame's worth, 1.5 MiB, may stay).
    std::vector<crowdgpu_event> room(200'000);
    const std::size_t heapBeforeList = heapInUse();
    const std::uint32_t some[100] = {};
    EXPECT_GT(crowd.events(some, 100, 0.0, 600.0, list, SIZE_MAX), 100'000u);
    list = {};
    ASSERT_EQ(crowdgpu_crowd_events(c, some, 100, 0.0, 600.0, room.data(), 200'000, &cCount), CROWDGPU_OK);
    EXPECT_LT(heapInUse(), heapBeforeList + (4u << 20)) << "bytes kept by the scratch lists after listing";
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
}

// Before: a window to +inf or 1e20 ran until memory ran out; now the ends are times in range and the
// window at most kLargestEventWindow long.
TEST(ApiArguments, EventWindowsAreBoundedAndTheirEndsAreTimes) {
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::Mill, 16);
    crowd.advanceTo(0.0);
    std::vector<crowdgpu::Event> events;
    const std::uint32_t first = 0;
    EXPECT_REFUSED("events: to", crowd.events(&first, 1, 0.0, kInf, events));
    EXPECT_REFUSED("events: to", crowd.events(&first, 1, 0.0, 1e20, events));
    EXPECT_REFUSED("longer than 3600 s", crowd.events(&first, 1, 0.0, crowdgpu::kLargestEventWindow + 0.5, events));
    EXPECT_REFUSED("ends before it starts", crowd.events(&first, 1, 1.0, 0.5, events));
    // The longest window, of a character walking in place: its footsteps.
    crowdgpu::Crowd inPlace = walkingCrowd(crowdgpu::Behaviour::InPlace, 1);
    inPlace.advanceTo(0.0);
    EXPECT_GT(inPlace.events(&first, 1, 0.0, crowdgpu::kLargestEventWindow, events, 0), 1000u);

    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 16, 1, CROWDGPU_MILL, &c), CROWDGPU_OK);
    std::uint32_t count = 0;
    std::uint32_t ids[16];
    for (std::uint32_t i = 0; i < 16; ++i) ids[i] = i;
    expectCRefused(crowdgpu_crowd_events(c, ids, 16, 0.0, kInf, nullptr, 0, &count), "events: to");
    expectCRefused(crowdgpu_crowd_events(c, ids, 16, 0.0, 1e20, nullptr, 0, &count), "events: to");
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
}

namespace {

// The library's view of the GpuTest's device with the features the library needs.
struct LentDevice {
    VkPhysicalDeviceVulkan11Features vulkan11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &vulkan11};
    VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &vulkan12};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan13};
    crowdgpu::Device device;

    explicit LentDevice(const gpu::VulkanContext& context) {
        crowdgpu::enableRequiredFeatures(features, vulkan11, vulkan12, vulkan13);
        device = {context.instance, context.physicalDevice, context.device, context.queueFamily, &features};
    }
};

// A C settings field set to any integer, as a C host may: written as bytes, never as the C++ type.
template <class Field>
void store(Field& field, std::int32_t value) {
    static_assert(sizeof(Field) == 4);
    std::memcpy(&field, &value, 4);
}

}  // namespace

// Before: a culling, animation or shadow raster outside its enum silently meant the first value, and
// a C enum or bool outside its range was undefined behaviour (UBSan stopped c_api_smoke).
TEST_F(GpuTest, RendererEnumValuesOutsideTheirEnumsAreRefusedNamingThem) {
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::InPlace, 4);
    const VkPhysicalDevice physical = context->physicalDevice;
    auto settingsWith = [](const std::function<void(crowdgpu::RendererSettings&)>& spoil) {
        crowdgpu::RendererSettings s;
        spoil(s);
        return s;
    };
    EXPECT_REFUSED("method 99", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.method = crowdgpu::Method(99); })));
    EXPECT_REFUSED("animation 2", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.animation = crowdgpu::Animation(2); })));
    EXPECT_REFUSED("culling 7", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.culling = crowdgpu::Culling(7); })));
    EXPECT_REFUSED("shadow raster -1", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.shadowRaster = crowdgpu::ShadowRaster(-1); })));
    EXPECT_REFUSED("raster mode 3", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.raster = crowdgpu::Raster(3); })));
    EXPECT_REFUSED("thresholds", crowdgpu::memoryNeeded(physical, crowd, settingsWith([](auto& s) { s.impostorThreshold = NAN; })));

    LentDevice lent(*context);
    crowdgpu::Renderer renderer(lent.device, crowd, {});
    EXPECT_REFUSED("setCulling: culling 5", renderer.setCulling(crowdgpu::Culling(5), true));
    EXPECT_REFUSED("setAnimation: animation 9", renderer.setAnimation(crowdgpu::Animation(9)));
    EXPECT_REFUSED("setShadowRaster: shadow raster 2", renderer.setShadowRaster(crowdgpu::ShadowRaster(2)));
    EXPECT_REFUSED("setMethod: method 6", renderer.setMethod(crowdgpu::Method(6)));
    EXPECT_EQ(renderer.settings().culling, crowdgpu::Culling::Gpu);
    EXPECT_EQ(renderer.settings().animation, crowdgpu::Animation::Gpu);

    // Through C: each value stored as a C host may, refused naming it.
    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 4, 1, CROWDGPU_IN_PLACE, &c), CROWDGPU_OK);
    crowdgpu_renderer_settings good;
    crowdgpu_renderer_settings_default(&good);
    auto cRefused = [&](const std::function<void(crowdgpu_renderer_settings&)>& spoil, const std::string& words) {
        crowdgpu_renderer_settings bad = good;
        spoil(bad);
        EXPECT_EQ(crowdgpu_memory_needed(physical, c, &bad), 0u) << words;
        EXPECT_NE(std::string(crowdgpu_last_error()).find(words), std::string::npos) << crowdgpu_last_error();
    };
    cRefused([](auto& s) { store(s.method, 99); }, "method 99");
    cRefused([](auto& s) { store(s.raster, -3); }, "raster mode -3");
    cRefused([](auto& s) { store(s.color_format, -1); }, "color_format: -1");
    cRefused([](auto& s) { store(s.samples, -8); }, "samples: -8");
    cRefused([](auto& s) { const unsigned char two = 2; std::memcpy(&s.lod, &two, 1); }, "lod: 2 is not a bool");
    cRefused([](auto& s) { const unsigned char seven = 7; std::memcpy(&s.edge_filter, &seven, 1); }, "edge_filter: 7");
    EXPECT_GT(crowdgpu_memory_needed(physical, c, &good), 0u) << crowdgpu_last_error();
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);
}

// Before: a format that is no VkFormat reached vkGetPhysicalDeviceFormatProperties (the validation layer
// reports it: this fixture fails on any message), and S8_UINT was taken for a depth format.
TEST_F(GpuTest, TargetFormatsAreCheckedBeforeAnyDriverCall) {
    crowdgpu::Crowd crowd = walkingCrowd(crowdgpu::Behaviour::InPlace, 4);
    LentDevice lent(*context);
    auto create = [&](VkFormat color, VkFormat depth) {
        crowdgpu::RendererSettings settings;
        settings.target.color = color;
        settings.target.depth = depth;
        return refusal("format", [&] { crowdgpu::Renderer(lent.device, crowd, settings); });
    };
    EXPECT_EQ(create(static_cast<VkFormat>(0x7fffffff), VK_FORMAT_D32_SFLOAT), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(create(VK_FORMAT_UNDEFINED, VK_FORMAT_D32_SFLOAT), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(create(VK_FORMAT_R8G8B8A8_SRGB, static_cast<VkFormat>(1000000)), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(create(VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT), crowdgpu::ErrorCode::Unsupported);  // depth as colour
    EXPECT_EQ(create(VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_S8_UINT), crowdgpu::ErrorCode::Unsupported);  // no depth
    EXPECT_EQ(create(VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_UNORM), crowdgpu::ErrorCode::Unsupported);

    // In C, and a frame time that is not a time.
    crowdgpu_renderer_settings settings;
    crowdgpu_renderer_settings_default(&settings);
    store(settings.color_format, 0x7fffffff);
    crowdgpu_model soldier = nullptr;
    ASSERT_EQ(crowdgpu_model_soldier(1, &soldier), CROWDGPU_OK);
    crowdgpu_crowd c = nullptr;
    ASSERT_EQ(crowdgpu_crowd_create_grid(&soldier, 1, 4, 1, CROWDGPU_IN_PLACE, &c), CROWDGPU_OK);
    const crowdgpu_device device{lent.device.instance, lent.device.physicalDevice, lent.device.device,
                                 lent.device.queueFamily, lent.device.enabledFeatures};
    crowdgpu_renderer r = nullptr;
    expectCRefused(crowdgpu_renderer_create(&device, c, &settings, &r), "target colour format 2147483647 is not a Vulkan 1.3 format");
    EXPECT_EQ(r, nullptr);
    crowdgpu_crowd_destroy(c);
    crowdgpu_model_destroy(soldier);

    crowdgpu::Renderer renderer(lent.device, crowd, {});
    crowdgpu::FrameView view = crowdgpu::lookAt(std::array{0.0f, 2.0f, 10.0f}.data(), std::array{0.0f, 1.0f, 0.0f}.data(),
                                                0.8f, 0.1f, 100.0f, {64, 64}, kNan);
    EXPECT_REFUSED("recordCompute: view.time", renderer.recordCompute(VK_NULL_HANDLE, 0, view, crowd));
}
