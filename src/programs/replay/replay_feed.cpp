#include "replay/replay_feed.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace replay {
namespace {

// Track indices in ascending order of `key(track)`, ties by index; sorted on a copy of the keys, since
// a comparison that follows placements into the recording is several cache misses at 1,000,000 tracks.
template <typename Key>
std::vector<std::uint32_t> sortedBy(std::size_t count, Key key) {
    std::vector<std::pair<double, std::uint32_t>> keyed(count);
    for (std::uint32_t i = 0; i < count; ++i) keyed[i] = {key(i), i};
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order(count);
    for (std::size_t i = 0; i < count; ++i) order[i] = keyed[i].second;
    return order;
}

// The typical and the longest time between a track's consecutive samples.
std::pair<double, double> sampleIntervals(const Recording& recording) {
    std::vector<double> intervals;
    for (const Track& track : recording.tracks)
        for (std::size_t i = 1; i < track.samples.size(); ++i)
            intervals.push_back(track.samples[i].time - track.samples[i - 1].time);
    if (intervals.empty()) return {1.0 / 25.0, 0.0};
    const double longest = *std::max_element(intervals.begin(), intervals.end());
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    return {intervals[intervals.size() / 2], longest};
}

// Beyond this the ring's memory outgrows its use; a longer gap in a track costs only an early visit
// of its bucket, in which nothing is due (the feed is correct for any ring size).
constexpr std::size_t kMaxRingBuckets = std::size_t{1} << 16;
// Buckets per sample interval. The bucket holding the horizon is visited at every advance until the
// horizon leaves it, with its tracks' share of the crowd: at one bucket per interval that was half the
// live tracks at every 60 fps frame (0.04 s samples), O(crowd) instead of O(changes).
constexpr double kBucketsPerInterval = 16.0;
constexpr std::size_t kPrefetchAhead = 8;

}  // namespace

ReplayFeed::ReplayFeed(const Recording& recording, std::vector<TrackPlacement> placements, FeedSettings settings)
    : recording_(recording), placements_(std::move(placements)), settings_(settings) {
    settings_.linger = std::max(settings_.linger, 0.0);
    settings_.lookahead = std::max(settings_.lookahead, 0.0);
    assert(std::all_of(placements_.begin(), placements_.end(), [&](const TrackPlacement& p) {
        return p.track < recording_.tracks.size() && !recording_.tracks[p.track].samples.empty();
    }));
    byStart_ = sortedBy(placements_.size(), [&](std::uint32_t k) { return startTime(k); });
    byEnd_ = sortedBy(placements_.size(), [&](std::uint32_t k) { return endTime(k); });
    next_.assign(placements_.size(), 0);
    live_.assign(placements_.size(), 0);
    if (!byStart_.empty()) origin_ = startTime(byStart_.front());
    const auto [typical, longest] = sampleIntervals(recording_);
    bucketSeconds_ = (typical > 0.0 ? typical : 1.0 / 25.0) / kBucketsPerInterval;
    const double span = std::ceil(longest / bucketSeconds_) + 3.0;
    ring_.resize(std::bit_ceil(static_cast<std::size_t>(std::clamp(span, 64.0, double(kMaxRingBuckets)))));
    restart();
}

const FeedChanges& ReplayFeed::advance(double time) {
    assert(std::isfinite(time));
    changes_.restarted = false;
    changes_.started.clear();
    changes_.samples.clear();
    changes_.ended.clear();
    if (time < time_) {
        restart();
        changes_.restarted = true;
    }
    time_ = time;
    start(time);
    deliver(time, time + settings_.lookahead);
    end(time);
    return changes_;
}

void ReplayFeed::restart() {
    std::fill(next_.begin(), next_.end(), 0u);
    std::fill(live_.begin(), live_.end(), std::uint8_t{0});
    for (std::vector<std::uint32_t>& bucket : ring_) bucket.clear();
    started_ = ended_ = 0;
    nextBucket_ = 0;  // the bucket of the earliest start
    time_ = -std::numeric_limits<double>::infinity();
}

void ReplayFeed::start(double time) {
    while (started_ < byStart_.size() && startTime(byStart_[started_]) <= time) {
        const std::uint32_t track = byStart_[started_++];
        if (endTime(track) < time) continue;  // over before it could be seen: never live
        live_[track] = 1;
        changes_.started.push_back(track);
        file(track, startTime(track));
    }
}

void ReplayFeed::deliver(double time, double horizon) {
    const std::int64_t last = bucketOf(horizon);
    if (last < nextBucket_) return;
    // After a jump longer than the ring every bucket is visited once; a track filed ahead of the
    // bucket being visited may be visited again with nothing due, which is harmless.
    const std::int64_t visits = std::min<std::int64_t>(last - nextBucket_ + 1, std::int64_t(ring_.size()));
    const std::size_t mask = ring_.size() - 1;
    for (std::int64_t v = 0; v < visits; ++v) {
        visiting_.swap(ring_[static_cast<std::size_t>(nextBucket_ + v) & mask]);
        for (std::size_t j = 0; j < visiting_.size(); ++j) {
            // A bucket's tracks lie anywhere in 1,000,000 placements: fetch ahead, or each visit
            // waits for memory twice (its placement, its cursor).
            if (j + kPrefetchAhead < visiting_.size()) {
                __builtin_prefetch(&placements_[visiting_[j + kPrefetchAhead]]);
                __builtin_prefetch(&next_[visiting_[j + kPrefetchAhead]]);
            }
            const std::uint32_t track = visiting_[j];
            if (report(track, time, horizon)) file(track, sampleTime(track, next_[track]));
        }
        visiting_.clear();
    }
    // The horizon's own bucket may hold samples just beyond it: it is visited again next time.
    nextBucket_ = last;
}

void ReplayFeed::end(double time) {
    // A track ending here had its last sample (<= its end < time <= the horizon) reported by deliver.
    for (; ended_ < byEnd_.size() && endTime(byEnd_[ended_]) < time; ++ended_) {
        const std::uint32_t track = byEnd_[ended_];
        if (!live_[track]) continue;  // skipped by start()
        live_[track] = 0;
        changes_.ended.push_back(track);
    }
}

bool ReplayFeed::report(std::uint32_t track, double time, double horizon) {
    const TrackPlacement& p = placements_[track];
    const std::vector<Sample>& samples = recording_.tracks[p.track].samples;
    std::uint32_t i = next_[track];
    // Past samples but the latest are skipped; the usual frame has none, so the search is rare.
    if (i + 1 < samples.size() && samples[i + 1].time + p.timeShift <= time) {
        const auto later = std::upper_bound(samples.begin() + i + 1, samples.end(), time,
                                            [&](double t, const Sample& s) { return t < s.time + p.timeShift; });
        i = static_cast<std::uint32_t>(later - samples.begin()) - 1;
    }
    for (; i < samples.size() && samples[i].time + p.timeShift <= horizon; ++i)
        changes_.samples.push_back(FeedSample{track, i, samples[i].time + p.timeShift, samples[i].x + p.dx, samples[i].z + p.dz});
    next_[track] = i;
    return i < samples.size();
}

double ReplayFeed::sampleTime(std::uint32_t track, std::uint32_t index) const {
    const TrackPlacement& p = placements_[track];
    return recording_.tracks[p.track].samples[index].time + p.timeShift;
}

double ReplayFeed::startTime(std::uint32_t track) const { return sampleTime(track, 0); }

double ReplayFeed::endTime(std::uint32_t track) const {
    const TrackPlacement& p = placements_[track];
    return recording_.tracks[p.track].samples.back().time + p.timeShift + settings_.linger;
}

std::int64_t ReplayFeed::bucketOf(double time) const {
    return static_cast<std::int64_t>(std::floor((time - origin_) / bucketSeconds_));
}

void ReplayFeed::file(std::uint32_t track, double time) {
    // A track that starts behind buckets already passed (its start fell within the last lookahead)
    // goes into the first bucket still to be visited.
    const std::int64_t bucket = std::max(bucketOf(time), nextBucket_);
    ring_[static_cast<std::size_t>(bucket) & (ring_.size() - 1)].push_back(track);
}

}  // namespace replay
