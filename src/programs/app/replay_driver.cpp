#include "app/replay_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace app {
namespace {

double firstTime(const replay::Recording& r, const replay::TrackPlacement& p) {
    return r.tracks[p.track].samples.front().time + p.timeShift;
}
double lastTime(const replay::Recording& r, const replay::TrackPlacement& p) {
    return r.tracks[p.track].samples.back().time + p.timeShift;
}

double earliestStart(const replay::Recording& recording, const std::vector<replay::TrackPlacement>& placements) {
    double earliest = std::numeric_limits<double>::infinity();
    for (const replay::TrackPlacement& p : placements) earliest = std::min(earliest, firstTime(recording, p));
    return std::isfinite(earliest) ? earliest : 0.0;
}

}  // namespace

ReplayDriver::ReplayDriver(const replay::Recording& recording, std::vector<replay::TrackPlacement> placements,
                           const ReplaySettings& settings)
    : settings_(settings),
      offset_(earliestStart(recording, placements)),
      // A character leaves once its last sample is drawn (the delay after it).
      linger_(settings.delay),
      feed_(recording, std::move(placements), {linger_, 0.0}),
      handles_(feed_.trackCount()) {}

std::uint32_t ReplayDriver::mostLive(const replay::Recording& recording,
                                     const std::vector<replay::TrackPlacement>& placements, double linger) {
    // Every start and end in time order (an end at the same time as a start after it: both live then).
    std::vector<std::pair<double, int>> events;
    events.reserve(2 * placements.size());
    for (const replay::TrackPlacement& p : placements) {
        events.emplace_back(firstTime(recording, p), +1);
        events.emplace_back(lastTime(recording, p) + linger, -1);
    }
    std::sort(events.begin(), events.end(),
              [](const auto& a, const auto& b) { return a.first < b.first || (a.first == b.first && a.second > b.second); });
    std::int64_t live = 0, most = 0;
    for (const auto& [time, change] : events) most = std::max(most, live += change);
    return static_cast<std::uint32_t>(most);
}

void ReplayDriver::respawnAll(crowdgpu::Crowd& crowd) {
    for (crowdgpu::CharacterHandle& h : handles_)
        if (h.generation != 0 && crowd.alive(h)) {
            crowd.remove(h);
            tracks_[h.slot] = -1;
            h = {};
        }
}

double ReplayDriver::update(crowdgpu::Crowd& crowd, double time) {
    if (tracks_.size() != crowd.size()) tracks_.assign(crowd.size(), -1);
    const replay::FeedChanges& changes = feed_.advance(time + offset_);
    double ingest = 0.0;
    if (changes.restarted) ingest += millisecondsOf([&] { respawnAll(crowd); });
    const replay::Recording& recording = feed_.recording();
    for (const std::uint32_t track : changes.started) {
        const replay::TrackPlacement& p = feed_.placement(track);
        const std::vector<replay::Sample>& samples = recording.tracks[p.track].samples;
        crowdgpu::Character c;
        c.model = settings_.model;
        c.motion = crowdgpu::MotionSource::HostSamples;
        c.position[0] = static_cast<float>(samples.front().x + p.dx);
        c.position[2] = static_cast<float>(samples.front().z + p.dz);
        if (samples.size() > 1)  // facing its first step (0 faces +z)
            c.heading = static_cast<float>(std::atan2(samples[1].x - samples[0].x, samples[1].z - samples[0].z));
        crowdgpu::CharacterHandle h;
        ingest += millisecondsOf([&] { h = crowd.spawn(c); });
        handles_[track] = h;
        tracks_[h.slot] = track;
    }
    who_.clear(), times_.clear(), xs_.clear(), zs_.clear();
    for (const replay::FeedSample& s : changes.samples) {
        const crowdgpu::CharacterHandle h = handles_[s.track];
        if (h.generation == 0) continue;  // started before a restart that dropped it
        who_.push_back(h);
        times_.push_back(s.time - offset_);
        xs_.push_back(static_cast<float>(s.x));
        zs_.push_back(static_cast<float>(s.z));
    }
    ingest += millisecondsOf([&] { crowd.drive({who_.data(), times_.data(), xs_.data(), zs_.data(), nullptr, who_.size()}); });
    for (const std::uint32_t track : changes.ended) {
        crowdgpu::CharacterHandle& h = handles_[track];
        if (h.generation == 0) continue;
        ingest += millisecondsOf([&] { crowd.remove(h); });
        tracks_[h.slot] = -1;
        h = {};
    }
    return ingest;
}

}  // namespace app
