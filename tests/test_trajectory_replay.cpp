// Replaying a recording (src/programs/replay/, docs/host-driven.md): copies tiled side by side and
// shifted in time, the feed against a hand-computed schedule and against a brute-force reference
// through steps, jumps and seeks, and path smoothing of a straight and a swaying walk.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "replay/path_smoothing.h"
#include "replay/replay_feed.h"
#include "replay/trajectory_copies.h"

using namespace replay;

// ---- Copies ----

namespace {

Track track(std::int64_t id, std::vector<Sample> samples) { return Track{id, std::move(samples)}; }

Recording recordingOf(std::vector<Track> tracks) {
    Recording r;
    r.tracks = std::move(tracks);
    summarize(r);
    return r;
}

// Two people over 0..10 s on the rectangle x 0..4, z -2..0.
Recording twoPeople() {
    return recordingOf({track(7, {{0.0, 0.0, 0.0}, {10.0, 4.0, -2.0}}), track(9, {{6.0, 1.0, -1.0}, {8.0, 2.0, 0.0}})});
}

}  // namespace

TEST(TrajectoryCopies, TilesANearSquareGridOfDisjointCopies) {
    const Recording r = twoPeople();
    const Tiling tiling = tileCopies(r, {.copies = 5, .seed = 3, .gap = 2.0});
    EXPECT_EQ(tiling.columns, 3u);
    EXPECT_EQ(tiling.rows, 2u);
    ASSERT_EQ(tiling.copies.size(), 5u);
    ASSERT_EQ(tiling.tracks.size(), 10u);
    for (std::uint32_t k = 0; k < 5; ++k) {
        EXPECT_DOUBLE_EQ(tiling.copies[k].dx, 6.0 * (k % 3));  // width 4 + gap 2
        EXPECT_DOUBLE_EQ(tiling.copies[k].dz, 4.0 * (k / 3));  // depth 2 + gap 2
        for (std::uint32_t t = 0; t < 2; ++t) {
            const TrackPlacement& p = tiling.tracks[k * 2 + t];
            EXPECT_EQ(p.copy, k);
            EXPECT_EQ(p.track, t);  // the file's id for a report: r.tracks[p.track].id
        }
    }
    for (std::size_t a = 0; a < 5; ++a)
        for (std::size_t b = a + 1; b < 5; ++b) {
            const Extent& e = r.info.extent;
            const CopyPlacement& ca = tiling.copies[a];
            const CopyPlacement& cb = tiling.copies[b];
            const double gapX = std::fabs(ca.dx - cb.dx) - e.width(), gapZ = std::fabs(ca.dz - cb.dz) - e.depth();
            EXPECT_GE(std::max(gapX, gapZ), 2.0 - 1e-12) << "copies " << a << " and " << b << " overlap";
        }
}

TEST(TrajectoryCopies, ShiftsInTimeBySeedWrappingAroundTheDuration) {
    const Recording r = twoPeople();
    const Tiling tiling = tileCopies(r, {.copies = 16, .seed = 3});
    EXPECT_DOUBLE_EQ(tiling.period, 10.0);
    EXPECT_EQ(tiling.copies[0].timeShift, 0.0) << "copy 0 is the recording as it is";
    std::set<double> shifts;
    for (const CopyPlacement& copy : tiling.copies) {
        EXPECT_GE(copy.timeShift, 0.0);
        EXPECT_LT(copy.timeShift, 10.0);
        shifts.insert(copy.timeShift);
    }
    EXPECT_EQ(shifts.size(), 16u) << "every copy walks at its own time";
    for (const TrackPlacement& p : tiling.tracks) {
        const double start = r.tracks[p.track].samples.front().time;
        const double shift = tiling.copies[p.copy].timeShift;
        // A start pushed past the recording's end comes round to its beginning: every copy is busy throughout.
        EXPECT_DOUBLE_EQ(p.timeShift, start + shift > 10.0 ? shift - 10.0 : shift);
        EXPECT_GE(start + p.timeShift, 0.0);
        EXPECT_LE(start + p.timeShift, 10.0);
    }
    const Tiling again = tileCopies(r, {.copies = 16, .seed = 3});
    const Tiling other = tileCopies(r, {.copies = 16, .seed = 4});
    EXPECT_EQ(again.copies[5].timeShift, tiling.copies[5].timeShift);
    EXPECT_NE(other.copies[5].timeShift, tiling.copies[5].timeShift);
}

// ---- The replay feed ----

namespace {

// Samples of one advance per track, in the order given; fails if a track's samples are not contiguous.
std::map<std::uint32_t, std::vector<std::pair<std::uint32_t, double>>> samplesByTrack(const FeedChanges& changes) {
    std::map<std::uint32_t, std::vector<std::pair<std::uint32_t, double>>> byTrack;
    std::set<std::uint32_t> closed;
    for (std::size_t i = 0; i < changes.samples.size(); ++i) {
        const FeedSample& s = changes.samples[i];
        EXPECT_EQ(closed.count(s.track), 0u) << "track " << s.track << "'s samples are split";
        byTrack[s.track].push_back({s.index, s.time});
        if (i + 1 < changes.samples.size() && changes.samples[i + 1].track != s.track) closed.insert(s.track);
    }
    return byTrack;
}

using Expected = std::map<std::uint32_t, std::vector<std::pair<std::uint32_t, double>>>;

}  // namespace

TEST(TrajectoryFeed, ReportsStartsSamplesAndEndsOnAHandComputedSchedule) {
    // A: 1.0, 1.5, 2.0 s; B: 1.2, 1.4 s. Linger 0.5 s: A ends after 2.5, B after 1.9. Lookahead 0.25 s.
    const Recording r = recordingOf({track(1, {{1.0, 10, 0}, {1.5, 11, 0}, {2.0, 12, 0}}), track(2, {{1.2, 20, 0}, {1.4, 21, 0}})});
    ReplayFeed feed(r, placeAsRecorded(r), {.linger = 0.5, .lookahead = 0.25});
    using V = std::vector<std::uint32_t>;

    const FeedChanges* c = &feed.advance(0.9);
    EXPECT_TRUE(c->started.empty() && c->samples.empty() && c->ended.empty());

    c = &feed.advance(1.0);
    EXPECT_EQ(c->started, V{0});
    EXPECT_EQ(samplesByTrack(*c), (Expected{{0, {{0, 1.0}}}}));  // 1.5 is beyond 1.0 + 0.25

    c = &feed.advance(1.3);
    EXPECT_EQ(c->started, V{1});
    EXPECT_EQ(samplesByTrack(*c), (Expected{{0, {{1, 1.5}}}, {1, {{0, 1.2}, {1, 1.4}}}}));
    EXPECT_TRUE(c->ended.empty());

    c = &feed.advance(2.0);
    EXPECT_EQ(samplesByTrack(*c), (Expected{{0, {{2, 2.0}}}}));
    EXPECT_EQ(c->ended, V{1});  // 1.4 + 0.5 < 2.0

    c = &feed.advance(2.5);
    EXPECT_TRUE(c->ended.empty()) << "2.0 + 0.5 is not before 2.5";
    c = &feed.advance(2.6);
    EXPECT_EQ(c->ended, V{0});
    EXPECT_FALSE(c->restarted);
    c = &feed.advance(3.0);
    EXPECT_TRUE(c->started.empty() && c->samples.empty() && c->ended.empty());

    // A seek back: everyone gone, and what holds at 1.3 reported afresh.
    c = &feed.advance(1.3);
    EXPECT_TRUE(c->restarted);
    EXPECT_EQ(c->started, (V{0, 1}));
    EXPECT_EQ(samplesByTrack(*c), (Expected{{0, {{0, 1.0}, {1, 1.5}}}, {1, {{0, 1.2}, {1, 1.4}}}}));
    EXPECT_TRUE(c->ended.empty());
    c = &feed.advance(1.3);
    EXPECT_FALSE(c->restarted) << "the same time again is no seek";
    EXPECT_TRUE(c->started.empty() && c->samples.empty());
}

TEST(TrajectoryFeed, PlacementsMoveSamplesInSpaceAndTime) {
    const Recording r = recordingOf({track(1, {{1.0, 10, -1}, {2.0, 11, -1}})});
    ReplayFeed feed(r, {TrackPlacement{0, 0, 0.0, 0.0, 0.0}, TrackPlacement{0, 3, 10.0, 100.0, -50.0}});
    const FeedChanges& c = feed.advance(11.0);
    EXPECT_EQ(c.started, (std::vector<std::uint32_t>{1})) << "track 0 began and ended before 11 s: never seen";
    EXPECT_TRUE(c.ended.empty());
    ASSERT_EQ(c.samples.size(), 1u);
    EXPECT_EQ(c.samples[0].track, 1u);
    EXPECT_DOUBLE_EQ(c.samples[0].time, 11.0);
    EXPECT_DOUBLE_EQ(c.samples[0].x, 110.0);
    EXPECT_DOUBLE_EQ(c.samples[0].z, -51.0);
    EXPECT_EQ(feed.placement(1).copy, 3u);
}

TEST(TrajectoryFeed, AJumpSkipsSamplesAlreadyPast) {
    // 0.0, 0.1, ... 1.0 s, looking 0.06 s ahead. From 0.05 to 0.55 the samples at 0.2-0.4 are past:
    // only the latest at or before 0.55 (0.5) and those within the lookahead (0.6) are handed over.
    std::vector<Sample> samples;
    for (int i = 0; i <= 10; ++i) samples.push_back({i / 10.0, double(i), 0.0});
    const Recording r = recordingOf({track(1, samples)});
    ReplayFeed feed(r, placeAsRecorded(r), {.lookahead = 0.06});
    EXPECT_EQ(samplesByTrack(feed.advance(0.05)), (Expected{{0, {{0, 0.0}, {1, 0.1}}}}));
    EXPECT_EQ(samplesByTrack(feed.advance(0.55)), (Expected{{0, {{5, 0.5}, {6, 0.6}}}}));
    EXPECT_EQ(samplesByTrack(feed.advance(0.6)), (Expected{}));
    EXPECT_EQ(samplesByTrack(feed.advance(0.65)), (Expected{{0, {{7, 0.7}}}}));
}

namespace {

// Tracks of random length and rate (25, 10 and 2.5 samples a second), some with a gap of minutes.
Recording randomRecording(std::uint32_t seed, int people) {
    std::mt19937 random(seed);
    std::vector<Track> tracks;
    const double steps[] = {0.04, 0.1, 0.4};
    for (int id = 0; id < people; ++id) {
        double time = std::uniform_real_distribution<double>(-5.0, 60.0)(random);
        const double step = steps[random() % 3];
        const int count = 1 + static_cast<int>(random() % 150);
        Track t{id, {}};
        for (int i = 0; i < count; ++i) {
            t.samples.push_back({time, double(id), double(i)});
            time += (random() % 100 == 0) ? std::uniform_real_distribution<double>(30.0, 200.0)(random) : step;
        }
        tracks.push_back(std::move(t));
    }
    return recordingOf(std::move(tracks));
}

// The feed's contract checked the slow way: every track's state after each advance, from scratch.
struct FeedReference {
    const Recording& recording;
    const std::vector<TrackPlacement>& placements;
    FeedSettings settings;
    std::vector<int> state;               // 0 waiting, 1 started, 2 ended, 3 over before an advance saw it
    std::vector<std::uint32_t> reported;  // samples reported so far
    double last = -1e300;

    void check(double time, const FeedChanges& changes) {
        const bool seek = time < last;
        EXPECT_EQ(changes.restarted, seek) << "at " << time;
        if (seek || state.empty()) {
            state.assign(placements.size(), 0);
            reported.assign(placements.size(), 0);
        }
        last = time;
        const auto byTrack = samplesByTrack(changes);
        std::set<std::uint32_t> started(changes.started.begin(), changes.started.end());
        std::set<std::uint32_t> ended(changes.ended.begin(), changes.ended.end());
        for (std::uint32_t k = 0; k < placements.size(); ++k) {
            const TrackPlacement& p = placements[k];
            const std::vector<Sample>& samples = recording.tracks[p.track].samples;
            const double start = samples.front().time + p.timeShift, end = samples.back().time + p.timeShift + settings.linger;
            const bool starts = state[k] == 0 && start <= time && !(end < time);
            ASSERT_EQ(started.count(k) == 1, starts) << "track " << k << " at " << time;
            if (state[k] == 0 && start <= time) state[k] = starts ? 1 : 3;  // 3: over unseen
            std::vector<std::pair<std::uint32_t, double>> due;
            if (state[k] == 1) {
                // Skip to the latest sample at or before the time; then all up to the horizon.
                std::uint32_t latest = reported[k];
                for (std::uint32_t i = reported[k]; i < samples.size(); ++i)
                    if (samples[i].time + p.timeShift <= time) latest = i;
                for (reported[k] = latest;
                     reported[k] < samples.size() && samples[reported[k]].time + p.timeShift <= time + settings.lookahead; ++reported[k])
                    due.push_back({reported[k], samples[reported[k]].time + p.timeShift});
            }
            const auto found = byTrack.find(k);
            ASSERT_EQ(found == byTrack.end() ? decltype(due){} : found->second, due) << "track " << k << " at " << time;
            const bool ends = state[k] == 1 && end < time;
            ASSERT_EQ(ended.count(k) == 1, ends) << "track " << k << " at " << time;
            if (ends) state[k] = 2;
        }
    }
};

}  // namespace

TEST(TrajectoryFeed, MatchesABruteForceReferenceThroughStepsJumpsAndSeeks) {
    const Recording r = randomRecording(11, 120);
    const Tiling tiling = tileCopies(r, {.copies = 3, .seed = 5});
    const FeedSettings settings{.linger = 0.3, .lookahead = 0.2};
    ReplayFeed feed(r, tiling.tracks, settings);
    FeedReference reference{r, tiling.tracks, settings, {}, {}};
    std::mt19937 random(2);
    // Frame steps, coarse steps, jumps longer than the feed's ring of buckets, and seeks back.
    const double steps[] = {1.0 / 60.0, 1.0 / 60.0, 1.0 / 60.0, 0.04, 0.5, 3.0, 250.0, 700.0};
    double time = -6.0;
    for (int call = 0; call < 1500; ++call) {
        if (random() % 200 == 0) time = std::uniform_real_distribution<double>(-6.0, 80.0)(random);
        else time += steps[random() % 8];
        if (time > 3000.0) time = 0.0;
        reference.check(time, feed.advance(time));
        if (::testing::Test::HasFatalFailure()) return;
    }
}

// ---- Path smoothing ----

namespace {

void expectSample(const Sample& s, double time, double x, double z) {
    EXPECT_DOUBLE_EQ(s.time, time);
    EXPECT_DOUBLE_EQ(s.x, x);
    EXPECT_DOUBLE_EQ(s.z, z);
}

// A walk along x at 1.2 m/s sampled at 25 fps, swaying sideways by `sway` metres at 0.85 Hz.
Recording swayingWalk(double sway) {
    Track t{5, {}};
    for (int i = 0; i <= 500; ++i) {
        const double time = i / 25.0;
        t.samples.push_back({time, 1.2 * time, sway * std::sin(2.0 * std::numbers::pi * 0.85 * time)});
    }
    return recordingOf({t});
}

}  // namespace

TEST(TrajectorySmoothing, AStraightWalkIsUnchangedAndEndpointsStay) {
    Recording r = swayingWalk(0.0);
    const Recording raw = r;
    const SmoothingReport report = smoothPaths(r, kDefaultSmoothingWindow);
    EXPECT_LT(report.maxDeviation, 1e-12);
    for (std::size_t i = 0; i < raw.tracks[0].samples.size(); ++i) EXPECT_EQ(r.tracks[0].samples[i].time, raw.tracks[0].samples[i].time);
    Recording swaying = swayingWalk(0.025);
    const Sample first = swaying.tracks[0].samples.front(), last = swaying.tracks[0].samples.back();
    smoothPaths(swaying, kDefaultSmoothingWindow);
    expectSample(swaying.tracks[0].samples.front(), first.time, first.x, first.z);
    expectSample(swaying.tracks[0].samples.back(), last.time, last.x, last.z);
}

TEST(TrajectorySmoothing, TakesSwayOutWithinItsReport) {
    Recording r = swayingWalk(0.025);
    const SmoothingReport report = smoothPaths(r, kDefaultSmoothingWindow);
    // A Gaussian of sigma 0.6 / sqrt(12) s keeps exp(-2 pi^2 sigma^2 f^2) = 0.65 of a 0.85 Hz sway.
    double amplitude = 0.0;
    for (const Sample& s : r.tracks[0].samples)
        if (s.time > 2.0 && s.time < 18.0) amplitude = std::max(amplitude, std::fabs(s.z));
    EXPECT_NEAR(amplitude, 0.025 * 0.652, 0.001);
    EXPECT_NEAR(report.maxDeviation, 0.025 * (1.0 - 0.652), 0.001);
    EXPECT_GT(report.meanDeviation, 0.0);
    EXPECT_LT(report.meanDeviation, report.maxDeviation);
    EXPECT_EQ(report.samples, 501u);
    EXPECT_EQ(report.maxId, 5);
    Recording off = swayingWalk(0.025);
    EXPECT_EQ(smoothPaths(off, 0.0).maxDeviation, 0.0);
    EXPECT_EQ(off.tracks[0].samples[10].z, swayingWalk(0.025).tracks[0].samples[10].z);
}
