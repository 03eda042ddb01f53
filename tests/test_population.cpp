// The live population (crowd/population.h, crowd/change_log.h, Crowd::spawn and remove): handles of
// slot and generation, stale handles refused, slots reused per model, the capacity's own error, and the
// change log a renderer uploads from. CPU only.
#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "crowd/crowd.h"
#include "crowdgpu/crowd.hpp"
#include "gpu/error.h"
#include "support/gpu_test.h"

namespace {

using test::horse;
using test::soldier;

crowd::Character at(float x, std::uint32_t model = 0) {
    crowd::Character c;
    c.model = model;
    c.position = glm::vec3(x, 0.0f, 0.0f);
    c.props = 0;
    return c;
}

template <class F>
std::string errorOf(F&& f, gpu::ErrorKind* kind = nullptr) {
    try {
        f();
    } catch (const gpu::Error& e) {
        if (kind) *kind = e.kind();
        return e.what();
    }
    return {};
}

TEST(Population, SlotsFollowTheCharactersThenEachModelsSpareSlots) {
    crowd::Crowd crowd({&soldier(), &horse()}, {at(0, 1), at(1, 0), at(2, 1)}, {}, crowd::Capacity{{3, 4}});
    // Characters 0..2 as given, then soldier spares (3 - 1 = 2), then horse spares (4 - 2 = 2).
    ASSERT_EQ(crowd.size(), 7u);
    const std::uint32_t expected[] = {1, 0, 1, 0, 0, 1, 1};
    for (std::uint32_t s = 0; s < crowd.size(); ++s) EXPECT_EQ(crowd.characters()[s].model, expected[s]) << s;
    EXPECT_EQ(crowd.population().live(), 3u);
    for (std::uint32_t s = 0; s < 3; ++s) EXPECT_TRUE(crowd.alive(s));
    for (std::uint32_t s = 3; s < 7; ++s) EXPECT_FALSE(crowd.alive(s));
    // A free slot is drawn by no one: its identity's scale is 0.
    EXPECT_EQ(crowd.identity(4).tintScale.w, 0.0f);
    EXPECT_GT(crowd.identity(0).tintScale.w, 0.0f);
}

TEST(Population, SpawnTakesASlotOfItsModelAndRemovalFreesIt) {
    crowd::Crowd crowd({&soldier(), &horse()}, {at(0, 0)}, {}, crowd::Capacity{{2, 1}});
    const crowd::Handle horseHandle = crowd.spawn(at(5, 1));
    EXPECT_EQ(crowd.characters()[horseHandle.slot].model, 1u);
    const crowd::Handle second = crowd.spawn(at(6, 0));
    EXPECT_EQ(crowd.characters()[second.slot].model, 0u);
    EXPECT_EQ(crowd.population().live(), 3u);
    // Past the capacity of a model: its own error, and nothing changes.
    gpu::ErrorKind kind{};
    const std::string full = errorOf([&] { crowd.spawn(at(7, 0)); }, &kind);
    EXPECT_EQ(kind, gpu::ErrorKind::CapacityExceeded);
    EXPECT_NE(full.find("taken"), std::string::npos) << full;
    EXPECT_EQ(crowd.population().live(), 3u);
    // Removed: the handle goes stale, every call refuses it, and the slot is the next soldier's.
    crowd.remove(second);
    EXPECT_FALSE(crowd.population().valid(second));
    const std::string stale = errorOf([&] { crowd.remove(second); });
    EXPECT_NE(stale.find("removed"), std::string::npos) << stale;
    EXPECT_NE(errorOf([&] { crowd.moveTo(second.slot, {1.0f, 1.0f}, 0.0); }), "");
    const crowd::Handle again = crowd.spawn(at(8, 0));
    EXPECT_EQ(again.slot, second.slot);
    EXPECT_EQ(again.generation, second.generation + 1);
    EXPECT_FALSE(crowd.population().valid(second)) << "an old handle stays stale when its slot is reused";
    EXPECT_TRUE(crowd.population().valid(again));
    // A handle that never was.
    EXPECT_NE(errorOf([&] { crowd.remove({99, 1}); }).find("no such slot"), std::string::npos);
    EXPECT_NE(errorOf([&] { crowd.remove({0, 0}); }), "");
}

TEST(Population, BatchesSpawnAndRemoveWholeOrNotAtAll) {
    crowd::Crowd crowd({&soldier(), &horse()}, {at(0, 0)}, {}, crowd::Capacity{{600, 300}});
    // 700 in one batch (planned on every core), each handle naming its own character.
    std::vector<crowd::Character> wave;
    for (std::uint32_t i = 0; i < 700; ++i) wave.push_back(at(static_cast<float>(i), i % 3 == 0 ? 1u : 0u));
    std::vector<crowd::Handle> handles(wave.size());
    crowd.spawn(wave.data(), wave.size(), handles.data());
    EXPECT_EQ(crowd.population().live(), 701u);
    for (std::size_t i = 0; i < wave.size(); ++i) {
        ASSERT_TRUE(crowd.population().valid(handles[i]));
        EXPECT_EQ(crowd.characters()[handles[i].slot].model, wave[i].model);
        EXPECT_EQ(crowd.characters()[handles[i].slot].position.x, wave[i].position.x);
    }
    // One more horse than is free: the batch is refused whole, naming the model.
    std::vector<crowd::Character> horses(300 - 234 + 1, at(0, 1));
    std::vector<crowd::Handle> none(horses.size());
    gpu::ErrorKind kind{};
    const std::string full = errorOf([&] { crowd.spawn(horses.data(), horses.size(), none.data()); }, &kind);
    EXPECT_EQ(kind, gpu::ErrorKind::CapacityExceeded);
    EXPECT_NE(full.find("horse"), std::string::npos) << full;
    EXPECT_EQ(crowd.population().live(), 701u);
    horses.pop_back();
    crowd.spawn(horses.data(), horses.size(), none.data());
    EXPECT_EQ(crowd.population().freeOf(1), 0u);
    // A removal batch with a stale handle, or one handle twice, is refused whole: nobody leaves.
    const std::vector<crowd::Handle> kept(handles.begin(), handles.begin() + 10);
    std::vector<crowd::Handle> bad = kept;
    bad.push_back({99999, 1});
    EXPECT_NE(errorOf([&] { crowd.remove(bad.data(), bad.size()); }).find("no such slot"), std::string::npos);
    bad.back() = kept[4];
    EXPECT_NE(errorOf([&] { crowd.remove(bad.data(), bad.size()); }).find("twice"), std::string::npos);
    for (const crowd::Handle& h : kept) EXPECT_TRUE(crowd.population().valid(h));
    EXPECT_EQ(crowd.population().live(), 767u);
    // Then it leaves whole, and the freed slots are the next ones of their models.
    crowd.remove(kept.data(), kept.size());
    EXPECT_EQ(crowd.population().live(), 757u);
    for (const crowd::Handle& h : kept) EXPECT_FALSE(crowd.population().valid(h));
    const crowd::Handle next = crowd.spawn(at(1, 0));
    EXPECT_EQ(next.slot, kept[8].slot) << "the soldier's slot freed last (kept[9] is a horse's)";
}

TEST(Population, ASpawnedCharacterMovesAsTheSameCharacterOfAFreshCrowd) {
    // In place, its motion depends on its description alone: the same in a crowd built fresh.
    crowd::Crowd live({&soldier()}, {}, {}, crowd::Capacity{{4}});
    crowd::Character c = at(3.0f);
    c.clip = static_cast<std::uint32_t>(soldier().findClip("walk"));  // a clip with footsteps
    c.timeOffset = 0.37f;
    c.speed = 1.1f;
    live.advanceTo(2.0);
    const crowd::Handle h = live.spawn(c);
    live.advanceTo(2.5);
    crowd::Crowd fresh({&soldier()}, {c});
    fresh.advanceTo(2.5);
    const crowd::MotionState a = live.stateAt(h.slot, 2.5), b = fresh.stateAt(0, 2.5);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.phase, b.phase);
    EXPECT_EQ(a.clipTo, b.clipTo);
    // It fired no event before it was spawned.
    std::vector<crowd::FiredEvent> events;
    live.events(std::vector<std::uint32_t>{h.slot}, 0.0, 2.5, events);
    for (const crowd::FiredEvent& e : events) EXPECT_GT(e.time, 2.0);
    EXPECT_FALSE(events.empty());
}

TEST(ChangeLog, AReaderGetsEachChangedSlotOnceAndEverythingWhenItFellBehind) {
    crowd::ChangeLog log(10);
    std::vector<std::uint32_t> seen;
    auto collect = [&](std::uint64_t since) {
        seen.clear();
        return log.forEachSince(since, [&](std::uint32_t s) { seen.push_back(s); });
    };
    EXPECT_FALSE(collect(crowd::ChangeLog::kEverything)) << "a reader that saw nothing takes everything";
    log.mark(3);
    log.mark(5);
    log.mark(3);
    const std::uint64_t first = log.seal();
    log.mark(5);
    log.mark(7);
    ASSERT_TRUE(collect(first));
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(seen, (std::vector<std::uint32_t>{5, 7}));
    ASSERT_TRUE(collect(first - 1));
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(seen, (std::vector<std::uint32_t>{3, 5, 7})) << "slot 5 once, for its latest change";
    // Past the generations kept, a late reader takes everything; so does one from before markAll.
    const std::uint64_t now = log.seal();
    log.markAll();
    EXPECT_FALSE(collect(now));
    for (std::size_t i = 0; i < crowd::ChangeLog::kKeptGenerations + 1; ++i) log.seal();
    EXPECT_FALSE(collect(now)) << "forgotten";
    EXPECT_TRUE(collect(now + 1)) << "the generation that changed everything was sealed: it has everything up to it";
}

TEST(Population, ThePublicApiRefusesStaleHandlesAndCountsTheLiving) {
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {3};
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, std::vector<crowdgpu::Character>(1), crowdgpu::Behaviour::InPlace,
                          1, capacity);
    EXPECT_EQ(crowd.size(), 3u);
    EXPECT_EQ(crowd.liveCount(), 1u);
    const crowdgpu::CharacterHandle a = crowd.spawn({}), b = crowd.spawn({});
    EXPECT_EQ(crowd.liveCount(), 3u);
    try {
        crowd.spawn({});
        ADD_FAILURE() << "a spawn past the capacity";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::CapacityExceeded) << e.what();
    }
    crowd.remove(a);
    EXPECT_FALSE(crowd.alive(a));
    EXPECT_TRUE(crowd.alive(b));
    try {
        crowd.remove(a);
        ADD_FAILURE() << "a stale handle removed again";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
    }
    EXPECT_THROW(crowd.stateAt(a.slot, 0.0), crowdgpu::Error);
    EXPECT_THROW(crowd.handle(a.slot), crowdgpu::Error);
    EXPECT_EQ(crowd.handle(b.slot).generation, b.generation);
}

}  // namespace
