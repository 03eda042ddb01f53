// Footsteps of the built-in models (model/footsteps.h), checked against the skinned mesh as the crowd
// draws it: a character walks by root motion, its feet are skinned (Model::pose, double precision)
// every 2 ms where stateAt puts it, and each foot's touchdown, measured there on its own terms, must
// have exactly one footstep of that foot within one 60 Hz frame, every step of every cycle.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "crowdgpu/crowd.hpp"
#include "crowdgpu/model.hpp"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr double kStep = 0.002;  // seconds between skinned poses

// The test's own idea of a foot, from the rest pose alone (not the skin weights the library uses):
// the vertices low on the model, on one side and, for four legs, fore or hind.
struct FootRegion {
    std::string joint;  // the joint its footsteps must name
    std::vector<std::size_t> vertices;
};

std::vector<FootRegion> footRegions(const crowdgpu::Model& model) {
    const std::vector<crowdgpu::Model::PosedVertex> rest = model.pose(model.clipCount(), 0.0f);
    const double low = 0.06 * model.height();
    double frontBack = 0.0;  // between fore and hind hooves: the mean z of the low vertices
    std::size_t lowCount = 0;
    for (const auto& v : rest)
        if (v.position[1] < low) frontBack += v.position[2], ++lowCount;
    frontBack /= static_cast<double>(std::max<std::size_t>(lowCount, 1));
    const bool fourLegs = model.name() == "horse";
    std::vector<FootRegion> feet;
    if (fourLegs)
        feet = {{"front_pastern_l", {}}, {"front_pastern_r", {}}, {"hind_pastern_l", {}}, {"hind_pastern_r", {}}};
    else
        feet = {{"foot_l", {}}, {"foot_r", {}}};
    for (std::size_t i = 0; i < rest.size(); ++i) {
        const double* p = rest[i].position;
        if (p[1] >= low) continue;
        const std::size_t side = p[0] > 0.0 ? 0 : 1;  // +x is the character's left
        feet[fourLegs ? (p[2] > frontBack ? 0 : 2) + side : side].vertices.push_back(i);
    }
    return feet;
}

// A foot's lowest vertex over time, in the world: its height and its speed over the ground.
struct FootSample {
    double time, height, speed;
};

// Poses at `times` in the world: stateAt's position, heading and phase, Model::pose at that phase.
std::vector<std::vector<std::array<double, 3>>> worldPoses(const crowdgpu::Crowd& crowd, const crowdgpu::Model& model,
                                                           const std::vector<double>& times) {
    std::vector<std::vector<std::array<double, 3>>> poses;
    for (double t : times) {
        const crowdgpu::CharacterState s = crowd.stateAt(0, t);
        const float duration = model.clipDuration(s.clipTo);
        const double cycle = s.phase - std::floor(s.phase);
        const std::vector<crowdgpu::Model::PosedVertex> pose = model.pose(s.clipTo, static_cast<float>(cycle * duration));
        const double c = std::cos(s.heading), sn = std::sin(s.heading);
        std::vector<std::array<double, 3>> world(pose.size());
        for (std::size_t i = 0; i < pose.size(); ++i) {
            const double* p = pose[i].position;
            world[i] = {s.position[0] + c * p[0] + sn * p[2], s.position[1] + p[1], s.position[2] - sn * p[0] + c * p[2]};
        }
        poses.push_back(std::move(world));
    }
    return poses;
}

// Touchdowns measured on the mesh: the foot's lowest vertex comes within 0.5 % of the model's height
// of the ground (the lowest that foot gets) and moves over it at under a tenth of the body's speed,
// having risen past half its highest lift since its last touchdown (docs/events.md#footsteps).
std::vector<double> touchdowns(const std::vector<FootSample>& track, double bodySpeed, double modelHeight) {
    double ground = 1e30, highest = -1e30;
    for (const FootSample& s : track) ground = std::min(ground, s.height), highest = std::max(highest, s.height);
    std::vector<double> result;
    bool up = false;
    for (const FootSample& s : track) {
        if (!up && s.height > ground + 0.5 * (highest - ground)) up = true;
        else if (up && s.height <= ground + 0.005 * modelHeight && s.speed <= 0.1 * bodySpeed) {
            result.push_back(s.time);
            up = false;
        }
    }
    return result;
}

struct Case {
    const char* model;
    std::uint32_t seed;
    const char* clip;
    float phase, rate;
};

// Worst |event - touchdown| over every foot and cycle; fails the test on a touchdown without exactly
// one footstep of its foot within a frame, or a footstep without a touchdown.
double checkFootsteps(const Case& c) {
    const crowdgpu::Model model = std::string(c.model) == "horse" ? crowdgpu::Model::horse(c.seed) : crowdgpu::Model::soldier(c.seed);
    const auto clip = static_cast<std::uint32_t>(model.findClip(c.clip));
    crowdgpu::Character character;
    character.clip = clip;
    character.phase = c.phase;
    crowdgpu::Crowd crowd({model}, {character});
    crowd.play(0, static_cast<std::int32_t>(clip), 0.0, 0.0f, c.rate);  // walk away by root motion
    const double cycle = model.clipDuration(clip) / c.rate;
    const double begin = 0.5 + cycle, end = begin + 3.0 * cycle;
    crowd.advanceTo(0.0);
    crowd.advanceTo(end + 1.0);

    // The feet are followed from a cycle before the window, so that each has risen before its first
    // touchdown in it.
    std::vector<double> times;
    for (double t = begin - cycle - kStep; t <= end + kFrame + kStep; t += kStep) times.push_back(t);
    const auto poses = worldPoses(crowd, model, times);
    const crowdgpu::CharacterState first = crowd.stateAt(0, begin), last = crowd.stateAt(0, end);
    const double bodySpeed = std::hypot(last.position[0] - first.position[0], last.position[2] - first.position[2]) / (end - begin);
    EXPECT_GT(bodySpeed, 0.5) << c.model << " " << c.clip << ": it should travel";

    std::vector<crowdgpu::Event> events;
    const std::uint32_t who = 0;
    crowd.events(&who, 1, begin, end, events);
    double worst = 0.0;
    std::size_t matched = 0, footsteps = 0;
    for (const crowdgpu::Event& e : events)
        if (model.eventName(e.clip, e.event) == "footstep") ++footsteps;
    for (const FootRegion& foot : footRegions(model)) {
        EXPECT_FALSE(foot.vertices.empty()) << foot.joint;
        if (foot.vertices.empty()) continue;
        std::vector<FootSample> track;
        for (std::size_t k = 1; k + 1 < poses.size(); ++k) {
            std::size_t lowest = foot.vertices[0];
            for (std::size_t v : foot.vertices)
                if (poses[k][v][1] < poses[k][lowest][1]) lowest = v;
            const double dx = poses[k + 1][lowest][0] - poses[k - 1][lowest][0], dz = poses[k + 1][lowest][2] - poses[k - 1][lowest][2];
            track.push_back({times[k], poses[k][lowest][1], std::hypot(dx, dz) / (2.0 * kStep)});
        }
        const std::vector<double> downs = touchdowns(track, bodySpeed, model.height());
        EXPECT_GE(downs.size(), 2u) << c.model << " " << c.clip << " " << foot.joint;
        const std::int32_t joint = model.findJoint(foot.joint);
        for (double down : downs) {
            // Touchdowns at the window's edges may have their footstep just outside it.
            if (down < begin + kFrame || down > end - kFrame) continue;
            std::vector<double> near;
            for (const crowdgpu::Event& e : events)
                if (model.eventName(e.clip, e.event) == "footstep" && model.eventJoint(e.clip, e.event) == joint &&
                    std::abs(e.time - down) <= kFrame)
                    near.push_back(e.time);
            EXPECT_EQ(near.size(), 1u) << c.model << " seed " << c.seed << " " << c.clip << " " << foot.joint
                                       << ": touchdown at " << down << " s";
            if (near.size() == 1) worst = std::max(worst, std::abs(near[0] - down)), ++matched;
        }
        for (const crowdgpu::Event& e : events) {
            if (model.eventName(e.clip, e.event) != "footstep" || model.eventJoint(e.clip, e.event) != joint) continue;
            const bool touches = std::any_of(downs.begin(), downs.end(), [&](double d) { return std::abs(e.time - d) <= kFrame; });
            EXPECT_TRUE(touches) << c.model << " " << c.clip << " " << foot.joint << ": footstep at " << e.time
                                 << " s with no touchdown within a frame";
        }
    }
    EXPECT_GT(matched, 0u);
    std::printf("%s seed %u %s (phase %.2f s, rate %.2f): %zu footsteps, worst %.1f ms from the mesh's touchdown\n",
                c.model, c.seed, c.clip, c.phase, c.rate, footsteps, 1000.0 * worst);
    return worst;
}

TEST(Footsteps, EveryFootstepIsWithinAFrameOfItsFootTouchingDownOnTheSkinnedMesh) {
    const Case cases[] = {
        {"soldier", 1, "walk", 0.0f, 1.0f},  {"soldier", 1, "run", 0.0f, 1.0f},
        {"soldier", 7, "walk", 0.37f, 1.1f}, {"soldier", 7, "run", 0.21f, 0.9f},
        {"horse", 1, "walk", 0.0f, 1.0f},    {"horse", 1, "gallop", 0.0f, 1.0f},
        {"horse", 7, "walk", 0.53f, 0.9f},   {"horse", 7, "gallop", 0.11f, 1.1f},
    };
    for (const Case& c : cases) EXPECT_LE(checkFootsteps(c), kFrame) << c.model << " " << c.clip;
}

TEST(Footsteps, EachFootStepsOncePerCycleAndIdleNotAtAll) {
    for (const crowdgpu::Model& model : {crowdgpu::Model::soldier(1), crowdgpu::Model::soldier(7), crowdgpu::Model::horse(1),
                                         crowdgpu::Model::horse(7)}) {
        for (std::uint32_t clip = 0; clip < model.clipCount(); ++clip) {
            std::vector<std::int32_t> joints;
            for (std::uint32_t e = 0; e < model.eventCount(clip); ++e) {
                EXPECT_EQ(model.eventName(clip, e), "footstep");
                joints.push_back(model.eventJoint(clip, e));
                if (e > 0) {
                    EXPECT_LE(model.eventTime(clip, e - 1), model.eventTime(clip, e));
                }
            }
            std::sort(joints.begin(), joints.end());
            const std::string name = model.clipName(clip);
            if (name == "idle") {
                EXPECT_TRUE(joints.empty()) << model.name() << " idle";
                continue;
            }
            std::vector<std::int32_t> feet;
            for (const char* foot : {"foot_l", "foot_r", "front_pastern_l", "front_pastern_r", "hind_pastern_l", "hind_pastern_r"})
                if (model.findJoint(foot) >= 0) feet.push_back(model.findJoint(foot));
            std::sort(feet.begin(), feet.end());
            EXPECT_EQ(joints, feet) << model.name() << " " << name << ": one footstep per foot per cycle";
        }
    }
}

}  // namespace
