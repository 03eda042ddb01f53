// Footsteps through crossfades (docs/events.md#firing): a soldier crossfading walk -> run or
// run -> walk, the fade starting anywhere in the cycle, steps once per foot, each footstep near its
// foot's touchdown measured on the crossfading character's own skinned mesh (the blended pose,
// Crowd::jointWorld): within one 60 Hz frame outside the fade, within 60 ms in it; and a pair of events whose blended point the phase meets, passes
// back and meets again fires once, at the first meeting, on the CPU as on the hand-solved quadratic.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/model.hpp"

namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr double kStep = 0.002;  // seconds between skinned poses
constexpr float kFade = 0.5f;

// The test's own feet: the bind pose's vertices below 6 % of the height, by side (+x is the left).
struct Foot {
    std::string joint;
    std::vector<std::size_t> vertices;
};

std::vector<Foot> soldierFeet(const model::SkinnedModel& m, double height) {
    std::vector<Foot> feet = {{"foot_l", {}}, {"foot_r", {}}};
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const glm::vec4& p = m.vertices[i].position;
        if (p.y < 0.06 * height) feet[p.x > 0.0f ? 0 : 1].vertices.push_back(i);
    }
    return feet;
}

// The vertices of `foot` at `time`, skinned in double with the crowd's blended joints (jointWorld x
// inverse bind), in the world.
std::vector<std::array<double, 3>> footVertices(const crowdgpu::Crowd& crowd, const model::SkinnedModel& m, const Foot& foot, double time) {
    std::vector<std::array<double, 12>> bones(m.skeleton.inverseBind.size());
    std::vector<bool> done(bones.size(), false);
    std::vector<std::array<double, 3>> result;
    for (std::size_t v : foot.vertices) {
        const gpu::SkinVertex& sv = m.vertices[v];
        std::array<double, 3> p{0.0, 0.0, 0.0};
        for (int k = 0; k < 4; ++k) {
            const double w = sv.weights[k];
            if (w == 0.0) continue;
            const std::uint32_t j = sv.joints[k];
            if (!done[j]) {
                float world[12];
                crowd.jointWorld(0, j, time, world);
                const glm::mat4& ib = m.skeleton.inverseBind[j];  // column-major
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 4; ++c) {
                        double sum = c == 3 ? world[r * 4 + 3] : 0.0;
                        for (int i = 0; i < 3; ++i) sum += double(world[r * 4 + i]) * ib[c][i];
                        bones[j][r * 4 + c] = sum;
                    }
                done[j] = true;
            }
            for (int r = 0; r < 3; ++r)
                p[r] += w * (bones[j][r * 4] * sv.position.x + bones[j][r * 4 + 1] * sv.position.y +
                             bones[j][r * 4 + 2] * sv.position.z + bones[j][r * 4 + 3]);
        }
        result.push_back(p);
    }
    return result;
}

// Steps of one foot are 0.7 s apart or more: a footstep this close to a touchdown is that step's.
constexpr double kSameStep = 0.1;

struct FadeResult {
    double worst = 0.0;      // |footstep - touchdown|, seconds, outside the fade
    double worstFade = 0.0;  // the same for touchdowns in the fade (a frame beyond its end included)
    std::size_t matched = 0;
    bool ok = true;
};

// A soldier plays `fromClip`, crossfades to `toClip` over kFade from `fadeStart` and keeps it. Every
// touchdown of each foot from a cycle before the fade to two after it must have exactly one footstep of
// that foot within a frame, and every footstep a touchdown. A touchdown on the blended mesh: the
// foot's lowest vertex within 0.5 % of the height of the lowest it gets, moving over the ground at
// under a tenth of the body's speed then (its root joint's travel over the surrounding 0.5 s), having risen past
// half the smaller of the two clips' lifts since its last touchdown (docs/events.md#footsteps, with
// the body's speed and lift of a character whose gait changes).
FadeResult checkFade(const crowdgpu::Model& model, std::uint32_t fromClip, std::uint32_t toClip, double fadeStart) {
    const model::SkinnedModel& m = model.data()->model;
    crowdgpu::Character character;
    character.clip = fromClip;
    crowdgpu::Crowd crowd({model}, {character});
    crowd.play(0, static_cast<std::int32_t>(fromClip), 0.0, 0.0f, 1.0f);  // walk (or run) away by root motion
    crowd.advanceTo(0.0);
    crowd.play(0, static_cast<std::int32_t>(toClip), fadeStart, kFade, 1.0f);
    const double begin = fadeStart - 1.6, end = fadeStart + kFade + 1.6;
    crowd.advanceTo(begin - 0.5);
    crowd.advanceTo(end + 1.0);  // both segments known: the steady one and the fade

    std::vector<crowdgpu::Event> events;
    const std::uint32_t who = 0;
    const double checkFrom = begin + 0.6, checkTo = end - 0.3;  // each foot has lifted before
    crowd.events(&who, 1, checkFrom - 0.1, checkTo + 0.1, events);
    FadeResult result;
    for (const Foot& foot : soldierFeet(m, model.height())) {
        struct Sample {
            double time, height, speed, body;
        };
        std::vector<std::vector<std::array<double, 3>>> poses;
        std::vector<double> times;
        for (double t = begin - kStep; t <= end + kStep; t += kStep) times.push_back(t), poses.push_back(footVertices(crowd, m, foot, t));
        std::vector<Sample> track;
        double ground = 1e30, liftFrom = -1e30, liftTo = -1e30;
        for (std::size_t k = 1; k + 1 < times.size(); ++k) {
            // The body's speed: its root joint's travel (stateAt answers for the current segment only).
            float a[12], b[12];
            crowd.jointWorld(0, 0, times[k] - 0.25, a);
            crowd.jointWorld(0, 0, times[k] + 0.25, b);
            const double body = std::hypot(b[3] - a[3], b[11] - a[11]) / 0.5;
            std::size_t v = 0;  // the lowest vertex, followed over the neighbouring poses for its speed
            for (std::size_t i = 0; i < poses[k].size(); ++i)
                if (poses[k][i][1] < poses[k][v][1]) v = i;
            const double height = poses[k][v][1];
            const double speed = std::hypot(poses[k + 1][v][0] - poses[k - 1][v][0], poses[k + 1][v][2] - poses[k - 1][v][2]) / (2.0 * kStep);
            track.push_back({times[k], height, speed, body});
            ground = std::min(ground, height);
            if (times[k] < fadeStart) liftFrom = std::max(liftFrom, height);
            if (times[k] > fadeStart + kFade) liftTo = std::max(liftTo, height);
        }
        const double rearm = ground + 0.5 * (std::min(liftFrom, liftTo) - ground);
        std::vector<double> downs;
        bool up = false;
        for (const Sample& s : track) {
            if (!up && s.height > rearm) up = true;
            else if (up && s.height <= ground + 0.005 * model.height() && s.speed <= 0.1 * s.body) downs.push_back(s.time), up = false;
        }
        const std::int32_t joint = model.findJoint(foot.joint);
        std::vector<double> steps;
        for (const crowdgpu::Event& e : events)
            if (model.eventName(e.clip, e.event) == "footstep" && model.eventJoint(e.clip, e.event) == joint) steps.push_back(e.time);
        for (double down : downs) {
            if (down < checkFrom || down > checkTo) continue;
            std::size_t near = 0;
            double nearest = 1e30;
            for (double s : steps)
                if (std::abs(s - down) <= kSameStep) ++near, nearest = std::min(nearest, std::abs(s - down));
            EXPECT_EQ(near, 1u) << model.clipName(fromClip) << " -> " << model.clipName(toClip) << " from " << fadeStart
                                << " s, " << foot.joint << ": touchdown at " << down << " s";
            if (near != 1) result.ok = false;
            else if (down >= fadeStart && down <= fadeStart + kFade + kFrame) result.worstFade = std::max(result.worstFade, nearest), ++result.matched;
            else result.worst = std::max(result.worst, nearest), ++result.matched;
        }
        for (double s : steps) {
            if (s < checkFrom + kSameStep || s > checkTo - kSameStep) continue;
            const bool touches = std::any_of(downs.begin(), downs.end(), [&](double d) { return std::abs(s - d) <= kSameStep; });
            EXPECT_TRUE(touches) << model.clipName(fromClip) << " -> " << model.clipName(toClip) << " from " << fadeStart
                                 << " s, " << foot.joint << ": footstep at " << s << " s with no touchdown of that step";
            if (!touches) result.ok = false;
        }
    }
    return result;
}

TEST(FadeFootsteps, OneStepPerFootWithinAFrameOfTheBlendedMeshThroughWalkRunFades) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1);
    const auto walk = static_cast<std::uint32_t>(soldier.findClip("walk")), run = static_cast<std::uint32_t>(soldier.findClip("run"));
    for (const auto& [from, to] : {std::pair{walk, run}, std::pair{run, walk}}) {
        double worst = 0.0, worstFade = 0.0;
        std::size_t matched = 0, failed = 0, fades = 0;
        // Fades starting every 0.05 s over a whole cycle of the clip faded from.
        for (double start = 3.0; start < 3.0 + soldier.clipDuration(from); start += 0.05, ++fades) {
            const FadeResult r = checkFade(soldier, from, to, start);
            worst = std::max(worst, r.worst);
            worstFade = std::max(worstFade, r.worstFade);
            matched += r.matched;
            failed += r.ok ? 0 : 1;
        }
        std::printf("soldier %s -> %s: %zu fades, %zu touchdowns matched, %zu fades failed, worst %.1f ms outside the fade, "
                    "%.1f ms in it\n",
                    soldier.clipName(from).c_str(), soldier.clipName(to).c_str(), fades, matched, failed, 1000.0 * worst,
                    1000.0 * worstFade);
        EXPECT_EQ(failed, 0u);
        EXPECT_LE(worst, kFrame);
        // Mid-fade the blended mesh touches down later than the blended point (docs/events.md#firing):
        // measured 31 ms (walk -> run) and 55 ms (run -> walk); held to what was measured.
        EXPECT_LE(worstFade, 0.06);
    }
}

}  // namespace

namespace {

// A soldier whose walk and run carry one event each at `walkPoint` and `runPoint` of their cycles,
// of one name and joint (a pair).
crowdgpu::Model soldierWithPair(double walkPoint, double runPoint) {
    model::SkinnedModel m = crowdgpu::Model::soldier(1).data()->model;
    const std::int32_t foot = crowdgpu::Model::soldier(1).findJoint("foot_l");
    for (anim::Clip& clip : m.clips) {
        if (clip.name == "walk") clip.events = {{"stomp", static_cast<float>(walkPoint) * clip.duration, foot}};
        else if (clip.name == "run") clip.events = {{"stomp", static_cast<float>(runPoint) * clip.duration, foot}};
        else clip.events.clear();
    }
    return crowdgpu::Model(std::make_shared<const crowdgpu::detail::ModelData>(crowdgpu::detail::ModelData{m, {}}));
}

}  // namespace

// Run -> walk with the walk's point 0.45 of a cycle after the run's and a fade short enough that the
// blended point moves faster than the slowing phase from a tenth of the way on: the phase less the
// point rises, falls back by about 0.07 cycles through the fade and rises again after it, so a point
// it reaches near its peak is met, passed back and met again. The rule: each point fires once, at the
// first meeting. The reference steps the crowd's own phase and weight (stateAt) every 0.1 ms and fires
// where the running maximum of the phase less the point passes a whole cycle.
TEST(FadeFootsteps, APointMetTwiceInAFadeFiresOnceAtTheFirstMeeting) {
    const double runPoint = 0.1, walkPoint = 0.55;
    const crowdgpu::Model soldier = soldierWithPair(walkPoint, runPoint);
    const auto walk = static_cast<std::uint32_t>(soldier.findClip("walk")), run = static_cast<std::uint32_t>(soldier.findClip("run"));
    const double walkRate = 1.0 / soldier.clipDuration(walk), runRate = 1.0 / soldier.clipDuration(run);
    ASSERT_GT(runRate, walkRate);
    const double drift = walkPoint - runPoint;
    // The point's speed (drift / fade) equals the phase's a tenth of the way through the fade.
    const auto fade = static_cast<float>(drift / (runRate - 0.1 * (runRate - walkRate)));
    std::size_t metTwice = 0, fired = 0;
    double worst = 0.0;
    for (double start = 2.0; start < 2.0 + soldier.clipDuration(run); start += 0.01) {
        crowdgpu::Character character;
        character.clip = run;
        crowdgpu::Crowd crowd({soldier}, {character});
        crowd.play(0, static_cast<std::int32_t>(run), 0.0, 0.0f, 1.0f);
        crowd.advanceTo(0.0);
        crowd.play(0, static_cast<std::int32_t>(walk), start, fade, 1.0f);
        const double from = start, to = start + fade + 1.5;  // stateAt answers from the fade's start
        crowd.advanceTo(to);
        std::vector<crowdgpu::Event> events;
        const std::uint32_t who = 0;
        crowd.events(&who, 1, from, to, events);

        // The reference: the unwrapped phase less the blended point, its running maximum and falls.
        std::vector<double> expected;
        double unwrapped = 0.0, previousPhase = 0.0, best = -1e30, previousG = 0.0;
        bool fell = false;
        for (double t = from; t <= to; t += 1e-4) {
            const crowdgpu::CharacterState s = crowd.stateAt(0, t);
            const double phase = s.phase - std::floor(s.phase);
            if (t > from) unwrapped += phase - previousPhase - std::round(phase - previousPhase);
            else unwrapped = phase;
            previousPhase = phase;
            const double w = s.clipTo == walk ? s.weight : 0.0;  // the walk's weight (0 while the run is steady)
            const double g = unwrapped - runPoint - drift * w;  // relative to the run's point
            if (t > from && g < previousG && std::floor(previousG) != std::floor(g)) fell = true;
            if (t > from && std::floor(g) > std::floor(best)) expected.push_back(t);
            best = t > from ? std::max(best, g) : g;
            previousG = g;
        }
        metTwice += fell ? 1 : 0;
        ASSERT_EQ(events.size(), expected.size()) << "fade from " << start << " s";
        for (std::size_t i = 0; i < events.size(); ++i) {
            EXPECT_NEAR(events[i].time, expected[i], 1e-3) << "fade from " << start << " s, event " << i;
            worst = std::max(worst, std::abs(events[i].time - expected[i]));
        }
        fired += events.size();
    }
    std::printf("run -> walk, fade %.3f s, drift %.2f cycles: %zu events, %zu fades fall back through a point, worst %.2f ms\n",
                fade, drift, fired, metTwice, 1000.0 * worst);
    EXPECT_GT(metTwice, 0u) << "no fade met a point twice: the case is not exercised";
}
