// The wake calendar (crowd/wake_calendar.h): an advance visits the characters whose plan runs out by
// its time, each once, and no other; stale entries (a wake time that moved) never wake a character.
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "crowd/wake_calendar.h"

namespace {

struct Wakes {
    std::map<std::uint32_t, double> at;
    double operator()(std::uint32_t c) const { return at.at(c); }
};

std::vector<std::uint32_t> takeDue(crowd::WakeCalendar& calendar, const Wakes& wakes, double time) {
    std::vector<std::uint32_t> due;
    calendar.takeDue(time, [&](std::uint32_t c) { return wakes(c); }, due);
    return due;
}

TEST(WakeCalendar, TakesExactlyTheCharactersDueAscendingAndOnce) {
    crowd::WakeCalendar calendar;
    Wakes wakes;
    // 0.50 and 0.51 share a bucket (1/32 s wide) with 0.52, which is not yet due at 0.515.
    wakes.at = {{7, 0.50}, {3, 0.51}, {5, 0.52}, {1, 2.0}, {9, crowd::WakeCalendar::kNever}};
    for (const auto& [c, wake] : wakes.at) calendar.file(c, wake);
    calendar.file(3, 0.51);  // filed twice: still taken once
    EXPECT_DOUBLE_EQ(calendar.earliest(), 0.5);
    EXPECT_TRUE(takeDue(calendar, wakes, 0.49).empty());
    EXPECT_EQ(takeDue(calendar, wakes, 0.515), (std::vector<std::uint32_t>{3, 7}));
    EXPECT_EQ(takeDue(calendar, wakes, 0.52), (std::vector<std::uint32_t>{5}));  // kept in its bucket
    EXPECT_EQ(takeDue(calendar, wakes, 1.9), (std::vector<std::uint32_t>{}));
    EXPECT_EQ(takeDue(calendar, wakes, 1e9), (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(calendar.earliest(), crowd::WakeCalendar::kNever) << "9 never wakes, nobody is left";
}

TEST(WakeCalendar, AWakeMovedEarlierOrLaterLeavesNoStaleWakeUp) {
    crowd::WakeCalendar calendar;
    Wakes wakes;
    wakes.at = {{4, 5.0}};
    calendar.file(4, 5.0);
    wakes.at[4] = 1.0;  // a command brought it forward: filed again
    calendar.file(4, 1.0);
    EXPECT_EQ(takeDue(calendar, wakes, 1.0), (std::vector<std::uint32_t>{4}));
    wakes.at[4] = 9.0;  // planned: its next wake, filed by the crowd
    calendar.file(4, 9.0);
    EXPECT_TRUE(takeDue(calendar, wakes, 5.0).empty()) << "the entry at 5 s went stale";
    EXPECT_EQ(takeDue(calendar, wakes, 9.0), (std::vector<std::uint32_t>{4}));
    EXPECT_TRUE(takeDue(calendar, wakes, 100.0).empty());
}

TEST(WakeCalendar, LateTimesKeepTheirBuckets) {
    // 1e9 s is 3.2e10 buckets: the keys are 64-bit.
    crowd::WakeCalendar calendar;
    Wakes wakes;
    wakes.at = {{0, 1e9 + 0.01}, {1, 1e9 + 0.04}};
    calendar.file(0, wakes(0));
    calendar.file(1, wakes(1));
    EXPECT_EQ(takeDue(calendar, wakes, 1e9 + 1.0 / 60.0), (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(takeDue(calendar, wakes, 1e9 + 2.0 / 60.0), (std::vector<std::uint32_t>{}));
    EXPECT_EQ(takeDue(calendar, wakes, 1e9 + 3.0 / 60.0), (std::vector<std::uint32_t>{1}));
}

}  // namespace
