// Reaching a late time costs no more than an early one, and looks the same: the living behaviours are
// episodes whose first state is closed form (crowd/mill.h, crowd/march.h), each episode lands exactly
// on the next one's first state (crowd/arrival.h), and scene time is a double that reaches the GPU's
// arithmetic relative to an epoch (crowd/epoch.h). Before, a milling crowd replanned every segment from
// 0 s (64 characters at 1e6 s: minutes) and time was a float (at 1e6 s, 62.5 ms steps).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "app/crowd_app.h"
#include "crowd/crowd.h"
#include "crowd/epoch.h"

namespace {

constexpr double kFrame = 1.0 / 60.0;

// Models outlive the crowds made of them: loaded once per list.
const app::CrowdModels& modelsOf(const std::string& list) {
    static std::map<std::string, app::CrowdModels> loaded;
    auto it = loaded.find(list);
    if (it == loaded.end()) it = loaded.emplace(list, app::loadModels(list, 1)).first;
    return it->second;
}

crowd::Crowd livingCrowd(const std::string& models, crowd::Behaviour behaviour, std::uint32_t count,
                         std::uint32_t seed) {
    app::SceneOptions scene;
    scene.model = models;
    scene.count = count;
    scene.seed = seed;
    scene.behaviour = static_cast<crowdgpu::Behaviour>(behaviour);
    // The programs' crowd, taken out of its public handle for the internals these tests check
    // (segments, epochs); the models stay alive in modelsOf's cache.
    crowdgpu::Crowd built = app::buildCrowd(modelsOf(models), scene);
    return std::move(*built.data().owned);
}

crowd::Crowd mill(std::uint32_t count = 64, std::uint32_t seed = 5) {
    return livingCrowd("soldier:3,horse:1", crowd::Behaviour::Mill, count, seed);
}

// A formation of both kinds of stander: soldiers (a standing clip) and horses (their walk held still).
crowd::Crowd march(const std::string& model, std::uint32_t count = 36) {
    return livingCrowd(model, crowd::Behaviour::March, count, 1);
}

float angleBetween(float a, float b) {
    return std::abs(std::remainder(a - b, 2.0f * std::numbers::pi_v<float>));
}

float cyclesBetween(float a, float b) { return std::abs(std::remainder(a - b, 1.0f)); }

// The farthest two crowds' characters are apart at `time` (both advanced to it).
float farthestApart(const crowd::Crowd& a, const crowd::Crowd& b, double time) {
    float farthest = 0.0f;
    for (std::uint32_t c = 0; c < a.size(); ++c)
        farthest = std::max(farthest, glm::distance(a.stateAt(c, time).position, b.stateAt(c, time).position));
    return farthest;
}

// Advances frame by frame over [from, to) and checks that every segment planned starts where the one
// before it was at that moment: within a behaviour's episode by construction, between episodes
// because each lands on the next one's closed-form start. Returns the boundaries seen.
std::uint32_t expectSeamlessSegments(crowd::Crowd& crowd, double from, double to) {
    crowd.advanceTo(from);
    std::vector<crowd::Segment> before = crowd.plans();
    std::uint32_t seams = 0;
    for (double t = from + kFrame; t < to; t += kFrame) {
        crowd.advanceTo(t);
        for (std::uint32_t c : crowd.lastChanged()) {
            const crowd::Segment& now = crowd.plans()[c];
            if (now.start == before[c].start) continue;
            const std::uint32_t model = crowd.characters()[c].model;
            const crowd::MotionState was = crowd::stateOf(before[c], now.start, crowd.library(), model);
            const crowd::MotionState is = crowd::stateOf(now, now.start, crowd.library(), model);
            EXPECT_LT(glm::distance(was.position, is.position), 1e-3f) << "character " << c << " at " << now.start;
            EXPECT_LT(angleBetween(was.heading, is.heading), 1e-3f) << "character " << c << " at " << now.start;
            // A standing clip may land at a rate a little off natural: a frame's worth of it at most.
            EXPECT_LT(cyclesBetween(was.phase, is.phase), 0.005f) << "character " << c << " at " << now.start;
            EXPECT_EQ(was.clipTo, is.clipFrom) << "character " << c << " at " << now.start;
            EXPECT_NEAR(was.weight, 1.0f, 1e-6f) << "a segment starts once the crossfade before it ended";
            before[c] = now;
            ++seams;
        }
    }
    return seams;
}

}  // namespace

TEST(ClosedFormStart, AMillingCrowdStartedAtTIsTheCrowdRunFromZeroToT) {
    crowd::Crowd stepped = mill(), started = mill();
    const double late = 30.0;
    for (double t = 0.0; t < late; t += kFrame) stepped.advanceTo(t);
    stepped.advanceTo(late);
    started.advanceTo(late);
    EXPECT_LT(farthestApart(stepped, started, late), 1e-5f);
    // ... without planning its way there: every character skipped at least one episode.
    EXPECT_LT(started.plannedSegments(), stepped.plannedSegments());
    // And on from there, frame by frame, the two stay one crowd.
    for (double t = late; t < late + 20.0; t += kFrame) stepped.advanceTo(t), started.advanceTo(t);
    EXPECT_LT(farthestApart(stepped, started, late + 20.0), 1e-5f);
}

TEST(ClosedFormStart, AMarchingFormationStartedAtTIsTheFormationRunFromZeroToT) {
    for (const char* model : {"soldier", "horse"}) {
        crowd::Crowd stepped = march(model), started = march(model);
        const double late = 120.0;  // into the third cycle
        for (double t = 0.0; t < late; t += kFrame) stepped.advanceTo(t);
        stepped.advanceTo(late);
        started.advanceTo(late);
        EXPECT_LT(farthestApart(stepped, started, late), 1e-5f) << model;
        EXPECT_LT(started.plannedSegments(), stepped.plannedSegments()) << model;
    }
}

TEST(ClosedFormStart, ALateStartPlansOneEpisodeACharacterNotEveryOneSinceZero) {
    // Before: 64 milling characters at 1e6 s replanned about 250,000 segments each, for minutes.
    for (const double late : {1e6, 1e7, 1e9}) {
        crowd::Crowd milling = mill();
        milling.advanceTo(late);
        // Stand, set off, a few legs on a long way, stop: a dozen segments is an episode's most.
        EXPECT_LE(milling.plannedSegments(), 12u * milling.size()) << late;
        crowd::Crowd marching = march("soldier");
        marching.advanceTo(late);
        EXPECT_LE(marching.plannedSegments(), 6u * marching.size()) << late;
    }
}

TEST(ClosedFormStart, EverySegmentStartsWhereTheLastLeftOffEarlyAndLate) {
    for (const double from : {0.0, 1e6, 1e9}) {
        crowd::Crowd milling = mill(128, 9);
        EXPECT_GT(expectSeamlessSegments(milling, from, from + 120.0), 5u * milling.size()) << from;
        for (const char* model : {"soldier", "horse"}) {
            crowd::Crowd marching = march(model, 16);
            EXPECT_GT(expectSeamlessSegments(marching, from, from + 120.0), 5u * marching.size()) << model << " " << from;
        }
    }
}

TEST(ClosedFormStart, GltfCharactersLandOnEveryEpisodeToo) {
    // Fox stands with its "Survey" clip; CesiumMan has only a walk, which it holds still to stand.
    const std::filesystem::path root(CROWD_SHARED_ASSETS_DIR);
    for (const char* file : {"fox/Fox.glb", "cesium-man/CesiumMan.glb"}) {
        if (!std::filesystem::exists(root / file)) GTEST_SKIP() << "shared asset " << (root / file) << " not present";
        for (const auto behaviour : {crowd::Behaviour::Mill, crowd::Behaviour::March}) {
            crowd::Crowd crowd = livingCrowd((root / file).string(), behaviour, 32, 4);
            EXPECT_GT(expectSeamlessSegments(crowd, 1e6, 1e6 + 150.0), 3u * crowd.size()) << file;
        }
    }
}

TEST(ClosedFormStart, AFormationKeepsItsGroundAndItsStepOverAnyNumberOfCycles) {
    // Each halt lands on where the member was laid out, facing as laid out, at the phase every member
    // starts the next cycle with: a million seconds (some 20,000 cycles) on, as in the first.
    for (const char* model : {"soldier", "horse"}) {
        for (const double from : {0.0, 1e6}) {
            crowd::Crowd formation = march(model, 16);
            const int standingClip = formation.model(0).findClip("idle");  // none: the horse holds its walk
            formation.advanceTo(from);
            std::vector<crowd::Segment> before = formation.plans();
            std::uint32_t halts = 0;
            for (double t = from + kFrame; t < from + 150.0; t += kFrame) {
                formation.advanceTo(t);
                // A cycle starts: everyone marches out at once, from standing.
                const gpu::MotionRecord& first = formation.plans()[0].motion;
                const bool fromStanding = standingClip >= 0 ? first.clips.x == static_cast<std::uint32_t>(standingClip)
                                                            : first.phase.y == 0.0f;
                const bool cycleStarts = formation.lastChanged().size() == formation.size() && fromStanding &&
                                         first.phase.z > 0.0f && formation.plans()[0].start != before[0].start;
                if (cycleStarts) {
                    const double start = formation.plans()[0].start;
                    const float phase = crowd::stateOf(before[0], start, formation.library(), 0).phase;
                    for (std::uint32_t c = 0; c < formation.size(); ++c) {
                        const crowd::MotionState halted = crowd::stateOf(before[c], start, formation.library(), 0);
                        const crowd::Character& laidOut = formation.characters()[c];
                        EXPECT_LT(glm::distance(halted.position, laidOut.position), 1e-3f) << model << " " << c;
                        EXPECT_LT(angleBetween(halted.heading, laidOut.heading), 1e-3f) << model << " " << c;
                        EXPECT_LT(cyclesBetween(halted.phase, phase), 1e-4f) << model << " " << c << ": in step";
                    }
                    ++halts;
                }
                before = formation.plans();
            }
            EXPECT_GE(halts, 2u) << model << " " << from;
        }
    }
}

TEST(ClosedFormStart, AStandingClipLandsOnItsPhaseAtANearlyNaturalRate) {
    // The rest before an episode plays the standing clip at whatever steady rate lands it on the next
    // episode's phase: never far from natural, so nobody fidgets or freezes.
    crowd::Crowd crowd = livingCrowd("soldier", crowd::Behaviour::Mill, 256, 3);
    const model::SkinnedModel& soldier = crowd.model(0);
    const auto idle = static_cast<std::uint32_t>(soldier.findClip("idle"));
    const float natural = 1.0f / soldier.clips[idle].duration;
    std::uint32_t stops = 0;
    for (double t = 0.0; t < 200.0; t += 0.1) {
        crowd.advanceTo(t);
        for (std::uint32_t c : crowd.lastChanged()) {
            const gpu::MotionRecord& m = crowd.plans()[c].motion;
            if (m.clips.y != idle || m.clips.x == idle) continue;  // not a stop
            EXPECT_NEAR(m.phase.z / natural, 1.0f, 0.35f) << "character " << c << " at " << crowd.plans()[c].start;
            ++stops;
        }
    }
    EXPECT_GT(stops, 256u);
}

TEST(ClosedFormStart, TheGpuSeesSmallTimesAtAnySceneTime) {
    // Every record the motion pass reads is relative to the crowd's epoch, at most kEpochSeconds (and a
    // crossfade) before the frame, so float keeps microseconds at 1e9 s as at 0 s.
    for (const double late : {0.0, 1e6, 1e9}) {
        crowd::Crowd crowd = mill(32);
        for (double t = late; t < late + 150.0; t += 0.25) {
            crowd.advanceTo(t);
            EXPECT_LE(t - crowd.epoch(), crowd::kEpochSeconds);
            EXPECT_GE(t, crowd.epoch());
            for (const gpu::MotionRecord& m : crowd.segments()) {
                ASSERT_LT(std::abs(m.timing.x), crowd::kEpochSeconds + 5.0) << t;
                ASSERT_LT(std::abs(m.phase.x), 2.0f) << t;
            }
        }
    }
}

TEST(ClosedFormStart, InPlaceCharactersAnimateFrameByFrameAtAnySceneTime) {
    // A character looping its clip in place from 0 s: at 1e7 s its phase moves a sixtieth of a second's
    // worth each frame, and equals the phase at the same point of its period near 0 s.
    const model::SkinnedModel& soldier = modelsOf("soldier").models.front().data()->model;
    const auto walk = static_cast<std::uint32_t>(soldier.findClip("walk"));
    const double period = soldier.clips[walk].duration;
    for (const double late : {1e6, 1e7, 1e9}) {
        crowd::Crowd crowd(soldier, {crowd::Character{walk}});
        const double early = late - std::floor(late / period) * period;  // the same point of the period
        crowd::Crowd reference(soldier, {crowd::Character{walk}});
        float previous = 0.0f;
        for (std::uint32_t frame = 0; frame < 4; ++frame) {
            crowd.advanceTo(late + frame * kFrame);
            reference.advanceTo(early + frame * kFrame);
            const float phase = crowd.stateAt(0, late + frame * kFrame).phase;
            EXPECT_LT(cyclesBetween(phase, reference.stateAt(0, early + frame * kFrame).phase), 1e-5f) << late;
            if (frame > 0) {
                EXPECT_NEAR(cyclesBetween(phase, previous), kFrame / period, 1e-5) << late;
            }
            previous = phase;
        }
    }
}
