#pragma once
// A recording replayed as time advances, told as changes: who appears, who leaves, and the samples
// that came due, so that a host spawns, moves and removes characters from them. A frame's work is
// what changed, not the crowd: 1,000,000 tracks in copies of the corridor (replay/trajectory_copies.h)
// have about 80,000 people walking at once at 25 samples a second, and a 60 fps frame hands over
// about 30,000 samples without looking at the other tracks.
#include <cstdint>
#include <vector>

#include "replay/trajectory.h"
#include "replay/trajectory_copies.h"

namespace replay {

struct FeedSettings {
    double linger = 0.0;     // seconds a track stays after its last sample before it ends
    double lookahead = 0.0;  // seconds ahead of the time whose samples are handed over already (interpolation)
};

// A sample of a replay's track, moved by its placement.
struct FeedSample {
    std::uint32_t track = 0;  // index into the feed's placements: the track's id in the replay
    std::uint32_t index = 0;  // the sample's index in its recorded track
    double time = 0.0;
    double x = 0.0, z = 0.0;
};

// What one advance changed. Between two seeks a track is reported started once, then its samples in
// time order and none twice, then ended once. Samples already in the past at an advance (older than
// the track's latest sample at or before the advance's time) are skipped, and a track that would
// start and end within one advance is not reported at all: a jump or a seek costs the tracks it
// lands among, not their histories. Advancing by less than a sample interval skips nothing.
struct FeedChanges {
    // Time went backwards (a seek): every track reported before is gone; respawn from `started`.
    bool restarted = false;
    std::vector<std::uint32_t> started;  // tracks whose first sample time <= time, by start time
    std::vector<FeedSample> samples;     // sample time <= time + lookahead, grouped by track, in time order
    std::vector<std::uint32_t> ended;    // tracks whose last sample time + linger < time, by end time
};

class ReplayFeed {
public:
    // Over `placements` of `recording`'s tracks (placeAsRecorded or tileCopies' tracks). The recording
    // must outlive the feed. Sorts the tracks by start and by end once: O(tracks log tracks).
    ReplayFeed(const Recording& recording, std::vector<TrackPlacement> placements, FeedSettings settings = {});

    // The changes from the previous advance's time to `time` (finite). O(changes), plus O(tracks) when
    // `time` is before the previous one (a seek, reported as restarted). The returned lists are reused
    // by the next call: no allocation once they have grown to a frame's size.
    const FeedChanges& advance(double time);

    std::size_t trackCount() const { return placements_.size(); }
    const TrackPlacement& placement(std::uint32_t track) const { return placements_[track]; }
    const Recording& recording() const { return recording_; }

private:
    void restart();
    void start(double time);
    void deliver(double time, double horizon);
    void end(double time);
    // Reports track's samples from its latest at or before `time` up to `horizon`; false when none are left.
    bool report(std::uint32_t track, double time, double horizon);
    double startTime(std::uint32_t track) const;
    double endTime(std::uint32_t track) const;
    double sampleTime(std::uint32_t track, std::uint32_t index) const;
    std::int64_t bucketOf(double time) const;
    void file(std::uint32_t track, double time);

    const Recording& recording_;
    std::vector<TrackPlacement> placements_;
    FeedSettings settings_;
    std::vector<std::uint32_t> byStart_, byEnd_;  // track indices sorted by start, by end time
    std::vector<std::uint32_t> next_;             // per track: its first sample not yet reported
    std::vector<std::uint8_t> live_;              // per track: reported started and not yet ended
    std::size_t started_ = 0, ended_ = 0;         // cursors into byStart_, byEnd_
    double time_ = 0.0;                           // the last advance's; -infinity after a restart

    // The live tracks with samples still to report, filed under the time of the next one in buckets of
    // bucketSeconds_ (a sixteenth of the usual sample interval, so the bucket at the horizon, visited
    // again each frame, holds few tracks): a ring of buckets from nextBucket_, so that an advance
    // visits only the buckets it passes.
    double origin_ = 0.0, bucketSeconds_ = 0.0025;
    std::vector<std::vector<std::uint32_t>> ring_;
    std::int64_t nextBucket_ = 0;
    std::vector<std::uint32_t> visiting_;  // the bucket being visited (swapped out, so refiling is safe)
    FeedChanges changes_;
};

}  // namespace replay
