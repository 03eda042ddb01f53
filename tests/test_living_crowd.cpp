// The living crowd (crowd/motion.h, behaviours.h, the animation jobs and render/animation_pass):
// jobs against the reference sampler and hand-computed poses, closed-form motion against hand-computed
// values, crossfades without jumps, planted feet without sliding, determinism, and GPU palettes and
// images against the CPU path.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "anim/blending_job.h"
#include "anim/local_to_model.h"
#include "anim/palette_job.h"
#include "anim/sample_clip.h"
#include "anim/sampling_job.h"
#include "anim/skinning_matrices.h"
#include "app/crowd_app.h"
#include "crowd/crowd.h"
#include "crowd/mill_schedule.h"
#include "crowd/plan_steps.h"
#include "gpu/vulkan_error.h"
#include "model/procedural_models.h"
#include "render/crowd_buffers.h"
#include "skin/cpu_skinning.h"
#include "support/gltf_builder.h"
#include "support/gpu_test.h"

namespace {

using test::GpuTest;
constexpr float kFrame = 1.0f / 60.0f;

using test::horse;
using test::soldier;

crowd::Character standingAt(glm::vec3 position, std::uint32_t clip = 0) {
    crowd::Character c;
    c.clip = clip;
    c.position = position;
    return c;
}

// ---- Jobs ----

TEST(AnimationJobs, SamplingJobMatchesSampleClipWhateverItsCursorsHold) {
    for (const model::SkinnedModel* m : {&soldier(), &horse()}) {
        anim::ClipLibrary library;
        library.addModel(m->skeleton, m->clips, {});
        const std::size_t joints = m->skeleton.jointCount();
        std::vector<anim::Transform> expected(joints), sampled(joints);
        std::vector<std::uint16_t> cursors(3 * joints, 0);
        std::mt19937 random(7);
        for (std::uint32_t clip = 0; clip < m->clips.size(); ++clip) {
            for (int i = 0; i < 40; ++i) {
                // Forward in small steps (the cursors' fast path), then anywhere, with garbage cursors.
                const float t = i < 20 ? 0.013f * static_cast<float>(i) : 5.0f * std::uniform_real_distribution<float>()(random);
                if (i >= 20) for (std::uint16_t& c : cursors) c = static_cast<std::uint16_t>(random() % 70);
                anim::sampleClip(m->clips[clip], t, m->skeleton.restPose, expected);
                const anim::SamplingJob job{&library, 0, clip, t, cursors, sampled};
                ASSERT_TRUE(job.validate());
                job.run();
                for (std::size_t j = 0; j < joints; ++j) {
                    EXPECT_LT(glm::length(expected[j].translation - sampled[j].translation), 1e-6f) << m->name;
                    EXPECT_GT(std::abs(glm::dot(expected[j].rotation, sampled[j].rotation)), 1.0f - 1e-6f) << m->name;
                    EXPECT_LT(glm::length(expected[j].scale - sampled[j].scale), 1e-6f) << m->name;
                }
            }
        }
    }
}

TEST(AnimationJobs, BlendingJobMixesHandComputedPoses) {
    const float quarter = std::numbers::pi_v<float> / 2.0f;
    const anim::Transform from{{0, 0, 0}, glm::quat(1, 0, 0, 0), {1, 1, 1}};
    // The same rotation written as -q must blend along the short way all the same.
    const glm::quat turned = glm::angleAxis(quarter, glm::vec3(0, 1, 0));
    const anim::Transform to{{2, 0, 0}, -turned, {3, 3, 3}};
    std::vector<anim::Transform> out(1);
    const std::vector<anim::Transform> a{from}, b{to};
    anim::BlendingJob{a, b, 0.5f, out}.run();
    EXPECT_NEAR(out[0].translation.x, 1.0f, 1e-6f);
    EXPECT_NEAR(out[0].scale.y, 2.0f, 1e-6f);
    // Halfway between 0 and 90 degrees about y is 45 degrees (nlerp is exact at the midpoint).
    EXPECT_GT(std::abs(glm::dot(out[0].rotation, glm::angleAxis(quarter / 2.0f, glm::vec3(0, 1, 0)))), 1.0f - 1e-6f);
}

TEST(AnimationJobs, PaletteJobMatchesTheMatrixHierarchy) {
    const model::SkinnedModel& m = soldier();
    anim::ClipLibrary library;
    library.addModel(m.skeleton, m.clips, {});
    std::vector<anim::Transform> locals(m.skeleton.jointCount());
    anim::sampleClip(m.clips[1], 0.37f, m.skeleton.restPose, locals);
    std::vector<glm::mat4> modelSpace(locals.size());
    anim::localToModel(m.skeleton.parents, locals, m.skeleton.rootTransform, modelSpace);
    crowd::Character c;
    c.position = {3, 0, -2};
    c.heading = 0.7f;
    c.scale = 1.3f;
    std::vector<gpu::BoneRows> expected(locals.size()), bones(locals.size());
    anim::skinningMatrices(modelSpace, m.skeleton.inverseBind, crowd::characterTransform(c), expected);
    std::vector<anim::Affine> scratch(locals.size());
    anim::PaletteJob{&library, 0, anim::placementAffine(c.position, c.heading, c.scale), locals, scratch, bones}.run();
    for (std::size_t j = 0; j < bones.size(); ++j)
        for (int r = 0; r < 3; ++r) {
            const glm::vec4 d = (&bones[j].row0)[r] - (&expected[j].row0)[r];
            EXPECT_LT(glm::length(d), 1e-5f) << "joint " << j;
        }
}

// ---- Closed-form motion ----

TEST(Motion, InPlaceSegmentKeepsThePapersClockAndPlace) {
    crowd::Character c = standingAt({1, 0, 2}, 1);
    c.timeOffset = 0.3f;
    c.speed = 1.1f;
    const crowd::Crowd crowd(soldier(), {c});
    const float duration = soldier().clips[1].duration;
    const crowd::MotionState s = crowd.stateAt(0, 2.0f);
    EXPECT_NEAR(s.phase, (0.3f + 1.1f * 2.0f) / duration, 1e-5f);
    EXPECT_EQ(s.position, glm::vec3(1, 0, 2));
    EXPECT_EQ(s.clipFrom, 1u);
    EXPECT_EQ(s.clipTo, 1u);
    EXPECT_EQ(s.weight, 1.0f);
}

TEST(Motion, AStraightWalkCoversOneStridePerCycleAlongItsHeading) {
    crowd::Crowd crowd(soldier(), {standingAt({0, 0, 0}, 1)});
    const anim::ClipLibrary& library = crowd.library();
    gpu::MotionRecord walk = crowd::inPlaceSegment(library, 0, 1, {5, 0, 7}, 0.6f, 1.0f, 0.0f, 1.0f);
    walk.phase.w = 1.0f;  // carried by root motion
    const float duration = library.duration(0, 1);
    const glm::vec2 stride = library.stride(0, 1);
    ASSERT_GT(glm::length(stride), 1.0f) << "the soldier's walk travels about 1.36 m a cycle";
    const crowd::MotionState s = crowd::evaluateMotion(walk, 1.0f + 3.0f * duration, library, 0);
    // turnToWorld by hand: heading h turns model +z to (sin h, cos h).
    const float c = std::cos(0.6f), sn = std::sin(0.6f);
    const glm::vec2 expected = 3.0f * glm::vec2(c * stride.x + sn * stride.y, c * stride.y - sn * stride.x);
    EXPECT_NEAR(s.position.x, 5.0f + expected.x, 1e-4f);
    EXPECT_NEAR(s.position.z, 7.0f + expected.y, 1e-4f);
    EXPECT_NEAR(s.phase, 3.0f, 1e-5f);
}

TEST(Motion, CrossfadePhaseRateRisesLinearlyAndTheWeightWithIt) {
    gpu::MotionRecord m{};
    m.timing = glm::vec4(10.0f, 0.5f, 0.0f, 0.0f);  // starts at 10 s, 0.5 s crossfade
    m.phase = glm::vec4(0.25f, 1.0f, 3.0f, 0.0f);    // 1 -> 3 cycles per second
    // Halfway: rate 2, weight 0.5; phase 0.25 + 1 x 0.25 + (3 - 1) x 0.25^2 / (2 x 0.5) = 0.625.
    EXPECT_NEAR(crowd::motionPhase(m, 0.25f), 0.625f, 1e-6f);
    EXPECT_NEAR(crowd::motionWeight(m, 0.25f), 0.5f, 1e-6f);
    // After it: 0.25 + 2 x 0.5 = 1.25 at its end, then 3 per second.
    EXPECT_NEAR(crowd::motionPhase(m, 1.5f), 1.25f + 3.0f, 1e-5f);
    EXPECT_EQ(crowd::motionWeight(m, 1.5f), 1.0f);
}

TEST(Motion, ATurnStopsAtItsHeading) {
    gpu::MotionRecord m{};
    m.origin.w = 0.5f;
    crowd::turnTowards(m, 0.5f - 3.0f, 2.0f);
    EXPECT_NEAR(m.timing.w, 1.5f, 1e-6f);
    EXPECT_NEAR(crowd::motionHeading(m, 0.75f), 0.5f - 1.5f, 1e-6f);
    EXPECT_NEAR(crowd::motionHeading(m, 9.0f), 0.5f - 3.0f, 1e-6f);
}

// ---- Behaviours and the API ----

crowd::Crowd millCrowd(std::uint32_t count, std::uint32_t seed) {
    app::SceneOptions scene;
    scene.model = "soldier:3,horse:1";
    scene.count = count;
    scene.seed = seed;
    scene.behaviour = crowdgpu::Behaviour::Mill;
    static const app::CrowdModels models = app::loadModels("soldier:3,horse:1", 1);
    crowdgpu::Crowd built = app::buildCrowd(models, scene);  // the static models keep its models alive
    return std::move(built.data().crowd());
}

TEST(Behaviours, TheSameSeedGivesTheSameCrowdAtAnyFrameRate) {
    crowd::Crowd stepped = millCrowd(64, 5), jumped = millCrowd(64, 5), other = millCrowd(64, 6);
    for (float t = 0.0f; t < 20.0f; t += kFrame) stepped.advanceTo(t);
    jumped.advanceTo(20.0f - kFrame / 2);
    stepped.advanceTo(20.0f - kFrame / 2);
    other.advanceTo(20.0f - kFrame / 2);
    bool differs = false;
    for (std::uint32_t c = 0; c < stepped.size(); ++c) {
        EXPECT_EQ(std::memcmp(&stepped.segments()[c], &jumped.segments()[c], sizeof(gpu::MotionRecord)), 0) << c;
        differs |= std::memcmp(&stepped.segments()[c], &other.segments()[c], sizeof(gpu::MotionRecord)) != 0;
    }
    EXPECT_TRUE(differs) << "another seed must give another crowd";
    // Back in time replays the same plans.
    jumped.advanceTo(3.0f);
    jumped.advanceTo(20.0f - kFrame / 2);
    for (std::uint32_t c = 0; c < stepped.size(); ++c)
        EXPECT_EQ(std::memcmp(&stepped.segments()[c], &jumped.segments()[c], sizeof(gpu::MotionRecord)), 0) << c;
}

// A milling crowd plans its share every second from its start: its characters set off over their first
// episode, each at its own offset, as later episodes start. (When the whole crowd set off within its
// first 3 s, those seconds planned 2.5-3 times the steady share: a stall a host saw at every start.)
TEST(Behaviours, AMillingCrowdPlansItsSteadyShareFromItsStart) {
    app::SceneOptions scene;
    scene.model = "soldier";
    scene.count = 3000;
    scene.behaviour = crowdgpu::Behaviour::Mill;
    static const app::CrowdModels models = app::loadModels("soldier", 1);
    crowdgpu::Crowd built = app::buildCrowd(models, scene);
    crowd::Crowd& crowd = built.data().crowd();
    const double episode = crowd::millEpisodeLength(crowd.library(), 0, crowd.gaits(0), crowd.behaviour());
    // Segments planned in each second of three episodes, at 60 frames a second.
    const auto seconds = static_cast<std::uint32_t>(3.0 * episode);
    std::vector<double> perSecond(seconds, 0.0);
    for (std::uint32_t frame = 0; frame < seconds * 60; ++frame) {
        const std::uint64_t before = crowd.plannedSegments();
        crowd.advanceTo(frame / 60.0);
        perSecond[frame / 60] += static_cast<double>(crowd.plannedSegments() - before);
    }
    // The steady share: the third episode's seconds (every character past its first by then).
    const auto steadyFrom = static_cast<std::uint32_t>(std::ceil(2.0 * episode));
    double steady = 0.0;
    for (std::uint32_t s = steadyFrom; s < seconds; ++s) steady += perSecond[s];
    steady /= static_cast<double>(seconds - steadyFrom);
    ASSERT_GT(steady, 100.0) << "the crowd mills";
    for (std::uint32_t s = 0; s < steadyFrom; ++s)
        EXPECT_LT(perSecond[s], 1.25 * steady) << "second " << s << " plans " << perSecond[s] << " segments, the steady share " << steady;
}

TEST(Behaviours, MillingCharactersStandWalkRunAndStayNearHome) {
    crowd::Crowd crowd = millCrowd(48, 3);
    std::set<std::string> played;
    float farthest = 0.0f;
    for (float t = 0.0f; t < 40.0f; t += 0.25f) {
        crowd.advanceTo(t);
        for (std::uint32_t c = 0; c < crowd.size(); ++c) {
            const crowd::MotionState s = crowd.stateAt(c, t);
            played.insert(crowd.modelOf(c).clips[s.clipTo].name);
            farthest = std::max(farthest, glm::distance(glm::vec2(s.position.x, s.position.z),
                                                        glm::vec2(crowd.characters()[c].position.x,
                                                                  crowd.characters()[c].position.z)));
        }
    }
    for (const char* clip : {"idle", "walk", "run", "gallop"}) EXPECT_TRUE(played.count(clip)) << clip;
    EXPECT_GT(farthest, 3.0f) << "they move";
    // Targets lie within millRadius of home; turning arcs and stopping carry them up to ~3 m past.
    EXPECT_LT(farthest, crowd.behaviour().millRadius + 3.0f) << "but stay near home";
}

TEST(Behaviours, AFormationComesBackToWhereItStartedAfterOneBeat) {
    app::SceneOptions scene;
    scene.count = 16;
    scene.behaviour = crowdgpu::Behaviour::March;
    static const app::CrowdModels models = app::loadModels("soldier", 1);
    crowdgpu::Crowd built = app::buildCrowd(models, scene);
    crowd::Crowd& crowd = built.data().crowd();
    // Stand 1 s, march out, turn about, march back, turn about, halt: then it marches out again. Find
    // the second departure: the first time after the first halt that the formation moves again.
    std::vector<float> departures;
    glm::vec3 previous = crowd.stateAt(0, 0.0f).position;
    bool moving = false;
    for (float t = 0.0f; t < 80.0f && departures.size() < 2; t += 0.05f) {
        crowd.advanceTo(t);
        const glm::vec3 p = crowd.stateAt(0, t).position;
        const bool now = glm::distance(p, previous) > 1e-4f;
        if (now && !moving) departures.push_back(t);
        moving = now;
        previous = p;
    }
    ASSERT_EQ(departures.size(), 2u) << "the formation marches, halts and marches again";
    for (std::uint32_t c = 0; c < crowd.size(); ++c) {
        const glm::vec3 start = crowd.characters()[c].position;
        const crowd::MotionState s = crowd.stateAt(c, departures[1]);
        EXPECT_LT(glm::distance(s.position, start), 0.6f) << "character " << c;
        EXPECT_NEAR(std::remainder(s.heading, 2.0f * std::numbers::pi_v<float>), 0.0f, 0.01f);
    }
    // In step: everyone at the same phase.
    for (std::uint32_t c = 1; c < crowd.size(); ++c)
        EXPECT_EQ(crowd.stateAt(c, departures[1] + 3.0f).phase, crowd.stateAt(0, departures[1] + 3.0f).phase);
}

TEST(CrowdApi, MoveToArrivesAndStops) {
    crowd::Crowd crowd(soldier(), {standingAt({0, 0, 0})});
    crowd.moveTo(0, {6.0f, -8.0f}, 1.0f);
    for (float t = 0.0f; t < 20.0f; t += kFrame) crowd.advanceTo(t);
    const crowd::MotionState s = crowd.stateAt(0, 20.0f);
    EXPECT_LT(glm::distance(glm::vec2(s.position.x, s.position.z), glm::vec2(6.0f, -8.0f)), 0.6f);
    EXPECT_EQ(soldier().clips[s.clipTo].name, "idle");
    EXPECT_EQ(s.weight, 1.0f);
    const gpu::MotionRecord before = crowd.segments()[0];
    EXPECT_THROW(crowd.play(0, 99, 21.0f), gpu::Error);
    EXPECT_THROW(crowd.moveTo(3, {0, 0}, 21.0f), gpu::Error);
    EXPECT_THROW(crowd.moveTo(0, {0, 0}, 21.0f, 0), gpu::Error) << "idle does not travel";
    // Refused commands leave the character as it was: still standing at its target later on.
    crowd.advanceTo(40.0f);
    EXPECT_EQ(std::memcmp(&before, &crowd.segments()[0], sizeof before), 0);
}

TEST(CrowdApi, TheReadmeExampleRunsAsWritten) {
    const model::SkinnedModel& soldier = ::soldier();
    const model::SkinnedModel& horse = ::horse();
    // As in docs/living-crowd.md, "The C++ API" (without the renderer).
    const std::vector<const model::SkinnedModel*> models = {&soldier, &horse};
    crowd::LayoutOptions layout;
    layout.count = 1000;
    crowd::BehaviourSettings mill;
    mill.kind = crowd::Behaviour::Mill;
    mill.seed = 7;
    crowd::Crowd crowd(models, crowd::gridLayout(models, layout), mill, crowd::Capacity{{2000, 2000}});  // slots per model
    const std::uint32_t hero = crowd.spawn({.clip = 0, .position = {0, 0, 0}, .model = 0}).slot;
    crowd.moveTo(hero, {12.0f, -4.0f}, 2.0f);
    std::string standing;
    for (std::uint32_t frame = 0; frame < 32 * 60; ++frame) {
        const float time = static_cast<float>(frame) / 60.0f;
        if (frame == 14 * 60) {
            const crowd::MotionState there = crowd.stateAt(hero, time);
            EXPECT_LT(glm::distance(glm::vec2(there.position.x, there.position.z), glm::vec2(12.0f, -4.0f)), 0.6f);
            standing = soldier.clips[there.clipTo].name;
            crowd.moveTo(hero, {0.0f, 0.0f}, time, soldier.findClip("run"), 1.1f);
        }
        // The soldier has no "wave": that command is a clear error, not a crash.
        if (frame == 30 * 60) {
            EXPECT_THROW(crowd.play(hero, soldier.findClip("wave"), time, 0.5f), gpu::Error);
        }
        crowd.advanceTo(time);
    }
    EXPECT_EQ(standing, "idle");
    const crowd::MotionState end = crowd.stateAt(hero, 32.0f);
    EXPECT_LT(glm::length(glm::vec2(end.position.x, end.position.z)), 0.6f);
    EXPECT_EQ(crowd.population().live(), 1001u);
    EXPECT_EQ(crowd.size(), 4000u);  // slots, living or free
}

// ---- Crossfades and feet ----

// Model-space positions of every joint (no placement), the pose as the viewer of the body sees it.
std::vector<glm::vec3> jointPositions(const crowd::Crowd& crowd, float time) {
    const model::SkinnedModel& m = crowd.model(0);
    std::vector<gpu::BoneRows> bones(m.skeleton.jointCount());
    crowd.animateCharacter(0, time, bones);
    const crowd::MotionState s = crowd.stateAt(0, time);
    const glm::mat4 place = glm::inverse(crowd::characterTransform({0, 0, 1, s.position, s.heading, 0, 1.0f}));
    std::vector<glm::vec3> joints;
    for (std::size_t j = 0; j < bones.size(); ++j) {
        // A joint's origin is where its bind-pose position goes: bone * inverse(inverseBind) * 0.
        const glm::vec4 bindOrigin = glm::inverse(m.skeleton.inverseBind[j]) * glm::vec4(0, 0, 0, 1);
        joints.push_back(glm::vec3(place * anim::fromRows(bones[j]) * bindOrigin));
    }
    return joints;
}

// The largest change of any joint's per-frame step over consecutive frames (|p(t+1) - 2 p(t) +
// p(t-1)|): a smooth motion, however fast, changes its step little; a pop changes it at once.
float largestJerk(const crowd::Crowd& crowd, float from, float to) {
    float largest = 0.0f;
    std::vector<glm::vec3> before = jointPositions(crowd, from), now = jointPositions(crowd, from + kFrame);
    for (float t = from + 2.0f * kFrame; t <= to; t += kFrame) {
        const std::vector<glm::vec3> after = jointPositions(crowd, t);
        for (std::size_t j = 0; j < now.size(); ++j) largest = std::max(largest, glm::length(after[j] - 2.0f * now[j] + before[j]));
        before = std::move(now);
        now = after;
    }
    return largest;
}

TEST(Crossfade, WalkToRunChangesNoJointsStepMoreThanTheGaitsThemselves) {
    // Bound: 1.5 x the largest change of a joint's per-frame step in steady walking or running,
    // measured in the body's own frame at 60 fps.
    auto crowdWith = [](float fade) {
        crowd::Crowd c(soldier(), {standingAt({0, 0, 0}, 1)});
        c.play(0, 1, 0.0f, 0.0f);
        c.play(0, 2, 2.0f, fade);
        for (float t = 0.0f; t < 6.0f; t += 0.5f) c.advanceTo(t);
        c.advanceTo(6.0f);
        return c;
    };
    const crowd::Crowd smooth = crowdWith(0.5f);
    const float steady = std::max(largestJerk(smooth, 0.5f, 1.9f), largestJerk(smooth, 3.0f, 5.0f));
    EXPECT_LT(largestJerk(smooth, 1.9f, 2.7f), 1.5f * steady) << "steady " << steady;
    // A cut instead of a crossfade jumps well past the bound: the test sees a pop.
    const crowd::Crowd cut = crowdWith(0.0f);
    EXPECT_GT(largestJerk(cut, 1.9f, 2.7f), 1.5f * steady);
}

// How far the planted part of the foot moves per frame, for one character moving by root motion from
// `start` to `end`: the largest over frames of the horizontal move of the centroid of its planted
// vertices. A vertex is planted from one frame to the next when it is within 2 cm of the ground in
// both and in the two frames either side: a foot resting on the ground, not one skimming past it.
float plantedSlide(const crowd::Crowd& crowd, float start, float end) {
    const model::SkinnedModel& m = crowd.model(0);
    std::vector<gpu::BoneRows> bones(m.skeleton.jointCount());
    std::vector<std::vector<skin::CpuSkinnedVertex>> frames;
    for (float t = start; t <= end; t += kFrame) {
        crowd.animateCharacter(0, t, bones);
        frames.push_back(skin::skinOnCpu(m, bones));
    }
    double worst = 0.0;
    for (std::size_t f = 2; f + 3 < frames.size(); ++f) {
        glm::dvec3 before(0.0), after(0.0);
        int planted = 0;
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            bool down = true;
            for (std::size_t k = f - 2; k <= f + 3; ++k) down &= frames[k][v].position.y <= 0.02;
            if (!down) continue;
            before += frames[f][v].position;
            after += frames[f + 1][v].position;
            ++planted;
        }
        if (planted == 0) continue;
        const glm::dvec3 d = (after - before) / static_cast<double>(planted);
        worst = std::max(worst, glm::length(glm::dvec2(d.x, d.z)));
    }
    return static_cast<float>(worst);
}

TEST(FootSliding, ThePlantedFootOfAWalkingOrRunningSoldierMovesUnderAFifthOfItsStride) {
    // Per frame at 60 fps the soldier travels 2.1 cm walking and 5.2 cm running; the centroid of its
    // planted vertices moves less than 15 % (walk) and 20 % (run) of that: 3.1 mm and 1.05 cm. Without
    // root motion (the clip in place) the same feet slide by more than half the travel.
    struct Gait {
        const char* clip;
        float fraction;
    };
    for (const Gait gait : {Gait{"walk", 0.15f}, Gait{"run", 0.20f}}) {
        const auto clip = static_cast<std::uint32_t>(soldier().findClip(gait.clip));
        crowd::Crowd moving(soldier(), {standingAt({0, 0, 0}, clip)});
        moving.play(0, clip, 0.0f, 0.0f);
        moving.advanceTo(0.0f);
        moving.advanceTo(4.0f);
        const float travel = glm::length(moving.library().stride(0, clip)) / moving.library().duration(0, clip) * kFrame;
        EXPECT_LT(plantedSlide(moving, 1.0f, 3.0f), gait.fraction * travel) << gait.clip;
        const crowd::Crowd inPlace(soldier(), {standingAt({0, 0, 0}, clip)});
        EXPECT_GT(plantedSlide(inPlace, 1.0f, 3.0f), 0.5f * travel) << gait.clip;
    }
}

TEST(BoneLayout, MillionsOfCharactersFallBackToTightlyPackedBoneBlocks) {
    // The H100's limits: 64-byte uniform offsets make a soldier's 21 rows (1,008 bytes) a 24-row block.
    VkPhysicalDeviceLimits limits{};
    limits.minUniformBufferOffsetAlignment = 64;
    limits.minStorageBufferOffsetAlignment = 16;
    limits.maxStorageBufferRange = 112u * 1024u;
    crowd::Crowd small(soldier(), std::vector<crowd::Character>(80, standingAt({0, 0, 0})));
    const render::BoneLayout aligned = render::planBones(limits, small);
    EXPECT_TRUE(aligned.aligned);
    EXPECT_EQ(aligned.offsets[1], 24u);
    EXPECT_EQ(aligned.totalRows, 81u * 24u);
    // 100 soldiers (23 joints with the rifle's and the flag's): 112 KiB range; aligned blocks need
    // 101 x 1,152 bytes, tight ones 101 x 1,104.
    crowd::Crowd many(soldier(), std::vector<crowd::Character>(100, standingAt({0, 0, 0})));
    const render::BoneLayout tight = render::planBones(limits, many);
    EXPECT_FALSE(tight.aligned);
    EXPECT_EQ(tight.offsets[1], 23u);
    EXPECT_LE(tight.bytes(), limits.maxStorageBufferRange);
}

// ---- GPU against CPU ----

// Characters in crossfades between random clips at random weights at `time`, placed near the origin.
crowd::Crowd crossfadingCrowd(std::vector<const model::SkinnedModel*> models, std::uint32_t count, float time) {
    std::vector<crowd::Character> characters;
    for (std::uint32_t i = 0; i < count; ++i) {
        crowd::Character c = standingAt({1.5f * static_cast<float>(i % 8), 0, 1.5f * static_cast<float>(i / 8)});
        c.model = i % models.size();
        c.timeOffset = 0.37f * static_cast<float>(i);
        c.scale = models[c.model]->height() > 5.0f ? 0.2f : 1.0f;
        characters.push_back(c);
    }
    crowd::Crowd crowd(models, characters);
    std::mt19937 random(11);
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t clips = static_cast<std::uint32_t>(crowd.modelOf(i).clips.size());
        // Started up to 1 s before `time` with a 1.2 s crossfade: weights spread over (0, 1).
        const float start = time - std::uniform_real_distribution<float>(0.0f, 1.0f)(random);
        crowd.play(i, static_cast<std::uint32_t>(random() % clips), start, 1.2f, 0.8f + 0.05f * static_cast<float>(i % 8));
    }
    return crowd;
}

struct PaletteError {
    double worst = 0.0;   // of skinned positions, in units of the model's height
    std::uint32_t compared = 0;
    std::uint32_t blending = 0;  // characters caught mid-crossfade
};

PaletteError comparePalettes(const gpu::VulkanContext& context, crowd::Crowd& crowd, float time) {
    test::RendererOptions options;
    options.size = {64, 64};
    options.method = skin::Method::Compute;
    options.cull.mode = render::CullMode::Off;
    options.shadows = false;
    test::TestRenderer renderer(context, crowd, options);
    renderer.renderFrame(time);
    renderer.finish();
    const std::vector<std::byte> bytes = test::readBuffer(context, renderer.buffers().bones());
    const auto* gpuBones = reinterpret_cast<const gpu::BoneRows*>(bytes.data());
    // Where each character's block is this frame (its mesh slot's: the record's ids.y).
    const std::vector<gpu::CharacterRecord> records = test::readCharacterRecords(context, renderer);
    PaletteError error;
    for (std::uint32_t c = 0; c < crowd.size(); ++c) {
        const model::SkinnedModel& m = crowd.modelOf(c);
        std::vector<gpu::BoneRows> cpu(m.skeleton.jointCount());
        crowd.animateCharacter(c, time, cpu);
        const std::span<const gpu::BoneRows> gpu(gpuBones + records[c].ids.y, cpu.size());
        const std::vector<skin::CpuSkinnedVertex> a = skin::skinOnCpu(m, cpu), b = skin::skinOnCpu(m, gpu);
        const double height = m.height() * crowd.characters()[c].scale;
        for (std::size_t v = 0; v < a.size(); ++v)
            error.worst = std::max(error.worst, glm::length(a[v].position - b[v].position) / height);
        ++error.compared;
        const float w = crowd.stateAt(c, time).weight;
        if (w > 0.05f && w < 0.95f) ++error.blending;
    }
    return error;
}

TEST_F(GpuTest, GpuPalettesEqualTheCpuJobsForBuiltInModelsMidCrossfade) {
    for (float time : {2.0f, 7.31f}) {
        crowd::Crowd crowd = crossfadingCrowd({&soldier(), &horse()}, 48, time);
        const PaletteError e = comparePalettes(*context, crowd, time);
        EXPECT_EQ(e.compared, 48u);
        EXPECT_GT(e.blending, 20u) << "most characters are mid-crossfade";
        EXPECT_LT(e.worst, 1e-5) << "at " << time << " s";
    }
}

// The mounted model (docs/cavalry.md) mid-crossfade between walk and gallop: horse and rider blended as one.
TEST_F(GpuTest, GpuPalettesEqualTheCpuJobsForTheCavalryMidCrossfade) {
    const model::SkinnedModel cavalry = test::loadModel("cavalry", 1);
    crowd::Crowd crowd = crossfadingCrowd({&cavalry, &soldier()}, 24, 2.0f);
    const PaletteError e = comparePalettes(*context, crowd, 2.0f);
    EXPECT_EQ(e.compared, 24u);
    EXPECT_GT(e.blending, 8u) << "most characters are mid-crossfade";
    EXPECT_LT(e.worst, 1e-5);
}

TEST_F(GpuTest, GpuPalettesEqualTheCpuJobsForStepAndCubicSplineClips) {
    // The test strip character with a LINEAR clip ("bend") and a STEP + CUBICSPLINE one ("hop").
    test::GltfBuilder b = test::stripCharacter();
    test::addHopAnimation(b);
    const model::SkinnedModel strip = test::loadText(b.gltf());
    crowd::Crowd crowd = crossfadingCrowd({&strip}, 16, 1.6f);
    const PaletteError e = comparePalettes(*context, crowd, 1.6f);
    EXPECT_GT(e.blending, 5u);
    EXPECT_LT(e.worst, 1e-5);
}

TEST_F(GpuTest, GpuPalettesEqualTheCpuJobsForTheSharedGltfAssets) {
    const std::filesystem::path root(CROWD_SHARED_ASSETS_DIR);
    std::vector<model::SkinnedModel> assets;
    for (const char* file : {"fox/Fox.glb", "cesium-man/CesiumMan.glb", "rigged-simple/RiggedSimple.glb"}) {
        if (!std::filesystem::exists(root / file)) GTEST_SKIP() << "shared asset " << (root / file) << " not present";
        assets.push_back(test::loadModel((root / file).string(), 1));
    }
    for (const model::SkinnedModel& asset : assets) {
        crowd::Crowd crowd = crossfadingCrowd({&asset}, 12, 3.3f);
        const PaletteError e = comparePalettes(*context, crowd, 3.3f);
        EXPECT_EQ(e.compared, 12u);
        EXPECT_LT(e.worst, 1e-5) << asset.name;
    }
}

app::Rgba8Image renderMill(const gpu::VulkanContext& context, render::AnimationPath path, float time) {
    crowd::Crowd crowd = millCrowd(96, 2);
    test::RendererOptions options;
    options.size = {160, 96};
    options.method = skin::Method::Compute;
    options.animation = path;
    test::TestRenderer renderer(context, crowd, options);
    // A few frames before `time`, so segment uploads of several generations are exercised.
    for (float t : {time - 3.0f, time - 1.0f, time - kFrame, time}) {
        renderer.camera = app::cameraOnPath(app::CameraPath::FlyOver, test::shapeOf(crowd), 160.0f / 96.0f, t);
        renderer.renderFrame(t);
    }
    return renderer.readback();
}

TEST_F(GpuTest, EitherAnimationPathDrawsTheSameMovingCrowd) {
    const app::Rgba8Image cpu = renderMill(*context, render::AnimationPath::Cpu, 9.0f);
    const app::Rgba8Image gpu = renderMill(*context, render::AnimationPath::Gpu, 9.0f);
    const app::Rgba8Image earlier = renderMill(*context, render::AnimationPath::Gpu, 8.0f);
    EXPECT_GT(test::fractionOfMatchingPixels(cpu, gpu, 2), 0.999);
    // ... and the crowd moves: a second earlier is another picture.
    EXPECT_LT(test::fractionOfMatchingPixels(gpu, earlier, 2), 0.98);
}

}  // namespace
