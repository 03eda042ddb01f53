// Motion quality of a real recorded crowd replayed by soldiers through the driven-agent API
// (app/replay_driver.h, docs/host-driven.md), on the CPU, against the recording itself: the Jülich
// corridor (../shared/trajectories; skipped with a message when absent). Each root lies on the recording
// at its sample times (after the delay); feet do not slide (the soldier's ankles: a foot is in contact
// while within 1 cm of its lowest height over the run, and its slip is its horizontal travel in contact);
// on --terrain hills every root stands on the hills.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "app/replay_driver.h"
#include "app/terrain_hills.h"
#include "crowdgpu/crowd.hpp"
#include "replay/path_smoothing.h"
#include "replay/trajectory_reader.h"

namespace {

std::filesystem::path corridorFile() {
    return std::filesystem::path(CROWD_SHARED_TRAJECTORIES_DIR) / "juelich-bidirectional-corridor.txt";
}

struct FootTrace {
    std::vector<glm::vec3> positions;  // one a frame while the character lives
};

struct ReplayMeasures {
    std::vector<double> slips;          // metres, one a contact
    double worstRoot = 0.0;             // metres from the recording at its sample times
    std::size_t rootChecks = 0;
    double worstGround = 0.0;           // metres off the hills (terrain runs)
    std::map<std::uint32_t, std::size_t> framesByClip;  // the dominant clip, over every living frame
};

// Replays the corridor's first `seconds` (at most its whole duration) at 60 fps (on hills with `hills`) and
// measures it.
ReplayMeasures replayCorridor(double seconds, bool hills) {
    const replay::Recording raw = replay::readTrajectories(corridorFile().string());
    replay::Recording smoothed = raw;
    replay::smoothPaths(smoothed, replay::kDefaultSmoothingWindow, replay::kDefaultSmoothingShift);
    const std::vector<replay::TrackPlacement> placements = replay::placeAsRecorded(smoothed);
    crowdgpu::CrowdCapacity capacity;
    capacity.perModel = {app::ReplayDriver::mostLive(smoothed, placements, 0.1)};
    capacity.drivenKeys = crowdgpu::kDrivenKeys;
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, {}, crowdgpu::Behaviour::InPlace, 1, capacity);
    app::TerrainSamples ground;
    if (hills) {
        const replay::Extent& e = smoothed.info.extent;
        ground = app::hillsAround(static_cast<float>(0.5 * (e.minX + e.maxX)), static_cast<float>(0.5 * (e.minZ + e.maxZ)),
                                  static_cast<float>(0.5 * std::max(e.width(), e.depth()) + 5.0));
        crowd.setTerrain(ground.heightfield());
    }
    app::ReplayDriver driver(smoothed, placements, {0, 0.1});
    const crowd::Crowd& internal = crowd.data().crowd();
    const std::uint32_t feet[2] = {static_cast<std::uint32_t>(crowd.models()[0].findJoint("foot_l")),
                                   static_cast<std::uint32_t>(crowd.models()[0].findJoint("foot_r"))};
    ReplayMeasures m;
    std::map<std::int64_t, FootTrace> traces[2];  // per track
    const double frame = 1.0 / 60.0;
    seconds = std::min(seconds, smoothed.info.duration() + 0.2);
    for (double t = 0.0; t <= seconds; t += frame) {
        driver.update(crowd, t);
        crowd.advanceTo(t);
        for (std::uint32_t slot = 0; slot < crowd.size(); ++slot) {
            const std::int64_t track = driver.trackOf(slot);
            if (track < 0) continue;
            const crowd::MotionState state = internal.stateAt(slot, t);
            ++m.framesByClip[state.weight < 0.5f ? state.clipFrom : state.clipTo];
            if (hills)
                m.worstGround = std::max(m.worstGround, static_cast<double>(std::abs(
                                                            state.position.y - app::hillsHeight(state.position.x, state.position.z))));
            for (int f = 0; f < 2; ++f) {
                float rows[12];
                crowd.jointWorld(slot, feet[f], t, rows);
                traces[f][track].positions.emplace_back(rows[3], rows[7], rows[11]);
            }
            // The recording's samples drawn this frame (its time less the delay): the root is on them.
            const replay::TrackPlacement& p = driver.feed().placement(static_cast<std::uint32_t>(track));
            for (const replay::Sample& s : raw.tracks[p.track].samples) {
                const double drawn = s.time - driver.offset() + 0.1;
                if (!(drawn > t - frame && drawn <= t)) continue;
                const crowd::MotionState at = internal.stateAt(slot, drawn);
                m.worstRoot = std::max(m.worstRoot, std::hypot(at.position.x - s.x, at.position.z - s.z));
                ++m.rootChecks;
            }
        }
    }
    // Contacts: within 1 cm of the foot's lowest height over the character's run; slip: travel in contact.
    for (const auto& perFoot : traces)
        for (const auto& [track, trace] : perFoot) {
            float lowest = 1e30f;
            for (const glm::vec3& p : trace.positions) lowest = std::min(lowest, p.y);
            double slip = 0.0;
            bool inContact = false;
            for (std::size_t i = 0; i < trace.positions.size(); ++i) {
                const bool contact = trace.positions[i].y <= lowest + 0.01f;
                if (contact && inContact)
                    slip += std::hypot(trace.positions[i].x - trace.positions[i - 1].x, trace.positions[i].z - trace.positions[i - 1].z);
                if (!contact && inContact) m.slips.push_back(slip), slip = 0.0;
                inContact = contact;
            }
            if (inContact) m.slips.push_back(slip);
        }
    return m;
}

TEST(ReplayMotion, TheCorridorReplayedStaysOnItsPathsAndItsFeetDoNotSlide) {
    if (!std::filesystem::exists(corridorFile()))
        GTEST_SKIP() << "the shared recordings are absent (" << corridorFile() << "): nothing to replay";
    const ReplayMeasures m = replayCorridor(1e9, false);  // every character, start to end
    ASSERT_FALSE(m.slips.empty());
    std::vector<double> slips = m.slips;
    std::sort(slips.begin(), slips.end());
    const double mean = std::accumulate(slips.begin(), slips.end(), 0.0) / static_cast<double>(slips.size());
    const double p95 = slips[slips.size() * 95 / 100];
    std::printf("corridor, whole: %zu contacts, slip mean %.2f cm, p95 %.2f cm, max %.2f cm; root off the recording "
                "by %.2f cm at most over %zu samples\n",
                slips.size(), 100.0 * mean, 100.0 * p95, 100.0 * slips.back(), 100.0 * m.worstRoot, m.rootChecks);
    for (const auto& [clip, frames] : m.framesByClip) std::printf("  clip %u: %zu character-frames\n", clip, frames);
    EXPECT_GT(m.slips.size(), 1000u);
    EXPECT_LE(mean, 0.02);
    EXPECT_LE(p95, 0.05);
    EXPECT_GT(m.rootChecks, 5000u);
    EXPECT_LE(m.worstRoot, 0.10);
}

TEST(ReplayMotion, OnHillsEveryRootStandsOnTheGround) {
    if (!std::filesystem::exists(corridorFile()))
        GTEST_SKIP() << "the shared recordings are absent (" << corridorFile() << "): nothing to replay";
    const ReplayMeasures m = replayCorridor(15.0, true);
    std::printf("corridor on hills, 15 s: roots %.3f cm off the hills at most\n", 100.0 * m.worstGround);
    EXPECT_LE(m.worstGround, 0.01);
    EXPECT_LE(m.worstRoot, 0.10);
}

TEST(Terrain, TheHillsAreNoSteeperThanTwentyDegreesAndTheirGridFollowsThem) {
    EXPECT_LT(app::hillsSteepestDegrees(), 20.0f);
    const app::TerrainSamples t = app::hillsAround(3.0f, -7.0f, 60.0f);
    EXPECT_LT(app::steepestDegrees(t), 20.0f);
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, std::vector<crowdgpu::Character>(1));
    crowd.setTerrain(t.heightfield());
    for (float x = -50.0f; x <= 50.0f; x += 3.7f)
        for (float z = -60.0f; z <= 40.0f; z += 4.3f) EXPECT_NEAR(crowd.groundHeight(x, z), app::hillsHeight(x, z), 0.005f);
    // Past the grid, its edge goes on.
    EXPECT_FLOAT_EQ(crowd.groundHeight(1000.0f, -7.0f), crowd.groundHeight(t.origin[0] + t.size[0], -7.0f));
}

TEST(Terrain, ABadHeightfieldIsRefusedAndTheGroundStaysAsItWas) {
    crowdgpu::Crowd crowd({crowdgpu::Model::soldier(1)}, std::vector<crowdgpu::Character>(1));
    std::vector<float> heights = {0.0f, 1.0f, 2.0f, 3.0f};
    crowdgpu::Heightfield good{2, 2, heights.data(), {0.0f, 0.0f}, {2.0f, 2.0f}};
    crowd.setTerrain(good);
    auto refused = [&](crowdgpu::Heightfield field, const std::string& word) {
        try {
            crowd.setTerrain(field);
            ADD_FAILURE() << "accepted: " << word;
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
        EXPECT_FLOAT_EQ(crowd.groundHeight(2.0f, 2.0f), 3.0f) << "unchanged";
    };
    std::vector<float> nan = heights;
    nan[2] = std::nanf("");
    refused({2, 2, nan.data(), {0.0f, 0.0f}, {2.0f, 2.0f}}, "(0, 1) is not finite");
    refused({2, 2, heights.data(), {0.0f, 0.0f}, {0.0f, 2.0f}}, "extent");
    refused({1, 4, heights.data(), {0.0f, 0.0f}, {2.0f, 2.0f}}, "samples");
    refused({2, 2, nullptr, {0.0f, 0.0f}, {2.0f, 2.0f}}, "no heights");
    // And a character stands on the ground: its state's y is the ground's height.
    crowd.advanceTo(0.0);
    EXPECT_FLOAT_EQ(crowd.stateAt(0, 0.0).position[1], crowd.groundHeight(0.0f, 0.0f));
}

}  // namespace
