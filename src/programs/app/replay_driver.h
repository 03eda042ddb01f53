#pragma once
// A recorded (or simulated) crowd replayed by characters (docs/host-driven.md, "Recorded crowds"): each
// track of the recording, placed by its copy (replay/trajectory_copies.h), is a character driven from the
// host's memory that enters when its track starts, follows its samples and leaves when it ends. The
// replay's clock is the recording's, moved so that scene time 0 is its first sample.
#include <cstdint>
#include <vector>

#include "app/crowd_driver.h"
#include "replay/replay_feed.h"
#include "replay/trajectory.h"

namespace app {

struct ReplaySettings {
    std::uint32_t model = 0;  // the crowd's model the people are
    double delay = 0.1;       // crowdgpu::DrivenTiming::delay: two samples at 25 fps, and some jitter
};

class ReplayDriver : public CrowdDriver {
public:
    // The recording and placements must outlive the driver.
    ReplayDriver(const replay::Recording& recording, std::vector<replay::TrackPlacement> placements,
                 const ReplaySettings& settings);
    double update(crowdgpu::Crowd& crowd, double time) override;

    // Scene seconds of the recording's first sample: the replay is at recording time scene + offset.
    double offset() const { return offset_; }
    // The most tracks live at once, for the crowd's capacity.
    static std::uint32_t mostLive(const replay::Recording& recording, const std::vector<replay::TrackPlacement>& placements,
                                  double linger);
    // The track a slot's character replays, or -1 (a slot of no track now).
    std::int64_t trackOf(std::uint32_t slot) const { return slot < tracks_.size() ? tracks_[slot] : -1; }
    const replay::ReplayFeed& feed() const { return feed_; }
    double linger() const { return linger_; }

private:
    void respawnAll(crowdgpu::Crowd& crowd);

    ReplaySettings settings_;
    double offset_;
    double linger_;
    replay::ReplayFeed feed_;
    std::vector<crowdgpu::CharacterHandle> handles_;  // per track: its character (generation 0: none)
    std::vector<std::int64_t> tracks_;                // per slot: its track, or -1
    // The batch of a frame's samples, reused.
    std::vector<crowdgpu::CharacterHandle> who_;
    std::vector<double> times_;
    std::vector<float> xs_, zs_;
};

}  // namespace app
