// Cavalry (docs/cavalry.md): a rider seated on a mount's saddle joint as one character. The mount
// without a saddle is one clear error; the mounted horse moves exactly as the horse alone; the rider's
// hips stay on the saddle through a walk -> gallop crossfade (Crowd::jointWorld, the CPU path the GPU
// matches). The GPU skinning of the mounted model against the CPU reference is in test_gpu_skinning.cpp.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/crowdgpu.h"
#include "crowdgpu/error.hpp"
#include "crowdgpu/model.hpp"
#include "gpu/error.h"
#include "model/mounted_model.h"
#include "model/procedural_models.h"

namespace {

glm::dvec3 apply(const float rows[12], const glm::dvec3& p) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) r[i] = rows[4 * i] * p.x + rows[4 * i + 1] * p.y + rows[4 * i + 2] * p.z + rows[4 * i + 3];
    return r;
}
glm::dvec3 column(const float rows[12], int c) { return {rows[c], rows[4 + c], rows[8 + c]}; }

std::uint32_t joint(const crowdgpu::Model& model, const std::string& name) {
    const std::int32_t j = model.findJoint(name);
    EXPECT_GE(j, 0) << model.name() << " has no joint " << name;
    return static_cast<std::uint32_t>(std::max(j, 0));
}

}  // namespace

TEST(Cavalry, AMountWithoutTheSaddleJointIsOneClearError) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1), horse = crowdgpu::Model::horse(1);
    auto failure = [&](const crowdgpu::Model& mount, const std::string& saddle) -> std::string {
        try {
            crowdgpu::Model::mounted(mount, soldier, saddle);
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
            return e.what();
        }
        return "no error";
    };
    EXPECT_EQ(failure(soldier, "saddle"), "soldier: no joint 'saddle' to seat a rider on (a mount needs one)");
    EXPECT_EQ(failure(horse, "howdah"), "horse: no joint 'howdah' to seat a rider on (a mount needs one)");
    EXPECT_EQ(crowdgpu::Model::mounted(horse, soldier).name(), "soldier on horse");

    // The C API: the same message, its code, and no model handed out.
    crowdgpu_model cHorse = nullptr, cSoldier = nullptr, pair = nullptr;
    ASSERT_EQ(crowdgpu_model_horse(1, &cHorse), CROWDGPU_OK);
    ASSERT_EQ(crowdgpu_model_soldier(1, &cSoldier), CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_model_mounted(cSoldier, cSoldier, nullptr, &pair), CROWDGPU_ERROR_INVALID_ARGUMENT);
    EXPECT_STREQ(crowdgpu_last_error(), "soldier: no joint 'saddle' to seat a rider on (a mount needs one)");
    EXPECT_EQ(pair, nullptr);
    ASSERT_EQ(crowdgpu_model_mounted(cHorse, cSoldier, "saddle", &pair), CROWDGPU_OK);
    EXPECT_EQ(crowdgpu_model_clip_count(pair), 2u);
    crowdgpu_model_destroy(pair);
    crowdgpu_model_destroy(cSoldier);
    crowdgpu_model_destroy(cHorse);
}

TEST(Cavalry, TheMountedModelIsTheHorseAndTheSoldierWithTheHorsesClips) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1), horse = crowdgpu::Model::horse(1);
    const crowdgpu::Model cavalry = crowdgpu::Model::cavalry(1);
    EXPECT_EQ(cavalry.name(), "cavalry");
    EXPECT_EQ(cavalry.jointCount(), horse.jointCount() + soldier.jointCount());
    EXPECT_EQ(cavalry.vertexCount(), horse.vertexCount() + soldier.vertexCount());
    EXPECT_EQ(cavalry.triangleCount(), horse.triangleCount() + soldier.triangleCount());
    ASSERT_EQ(cavalry.clipCount(), horse.clipCount());
    for (std::uint32_t c = 0; c < horse.clipCount(); ++c) {
        EXPECT_EQ(cavalry.clipName(c), horse.clipName(c));
        EXPECT_EQ(cavalry.clipDuration(c), horse.clipDuration(c));
    }
    // The rider's joints are the soldier's, prefixed, its root under the saddle.
    const model::SkinnedModel& m = cavalry.data()->model;
    const std::uint32_t hips = joint(cavalry, "rider_hips"), saddle = joint(cavalry, "saddle");
    EXPECT_EQ(m.skeleton.parents[hips], static_cast<std::int32_t>(saddle));
    EXPECT_GE(cavalry.findJoint("rider_hand_r"), 0);
    EXPECT_GE(cavalry.findJoint("head"), 0) << "the horse's joints keep their names";
    EXPECT_EQ(m.materialColors.size(), horse.data()->model.materialColors.size() + soldier.data()->model.materialColors.size());
    // Taller than either: the soldier sits on top of the horse's back.
    EXPECT_GT(cavalry.height(), horse.height() + 0.3f);
}

// A joint's position in its character's own frame (where stateAt places it, turned back by its heading).
glm::dvec3 inBodyFrame(const crowdgpu::Crowd& crowd, std::uint32_t joint, double t) {
    float rows[12];
    crowd.jointWorld(0, joint, t, rows);
    const crowdgpu::CharacterState s = crowd.stateAt(0, t);
    const glm::dvec3 d = column(rows, 3) - glm::dvec3(s.position[0], s.position[1], s.position[2]);
    const double c = std::cos(s.heading), sn = std::sin(s.heading);
    return {c * d.x - sn * d.z, d.y, sn * d.x + c * d.z};
}

TEST(Cavalry, TheMountedHorseMovesExactlyAsTheHorseAlone) {
    // Every horse joint of a cavalryman, mid-crossfade and galloping, is the lone horse's joint in the
    // body's frame; and both travel at the same speed (root motion is measured from the hooves).
    const crowdgpu::Model horse = crowdgpu::Model::horse(1), cavalry = crowdgpu::Model::cavalry(1);
    crowdgpu::Character c;
    c.clip = static_cast<std::uint32_t>(horse.findClip("walk"));
    c.position[0] = 3.0f, c.heading = 0.7f, c.phase = 0.23f;
    crowdgpu::Crowd lone({horse}, {c}), mounted({cavalry}, {c});
    const auto gallop = horse.findClip("gallop");
    lone.play(0, gallop, 0.5, 0.4f), mounted.play(0, gallop, 0.5, 0.4f);
    double worst = 0.0;
    for (double t = 0.0; t <= 1.5; t += 1.0 / 30.0) {
        lone.advanceTo(t), mounted.advanceTo(t);
        for (std::uint32_t j = 0; j < horse.jointCount(); ++j)
            worst = std::max(worst, glm::length(inBodyFrame(lone, j, t) - inBodyFrame(mounted, j, t)));
    }
    EXPECT_LE(worst, 1e-5);
    const crowdgpu::CharacterState a = lone.stateAt(0, 1.5), b = mounted.stateAt(0, 1.5);
    const double apart = std::hypot(a.position[0] - b.position[0], a.position[2] - b.position[2]);
    EXPECT_LE(apart, 1e-4) << "the mounted horse travels as the horse alone";
}

// The test: through a walk -> gallop crossfade, sampled at 60 fps, the rider's hips stay within
// 0.12 m of their seat (where the hips sit at rest, carried by the saddle joint), sit between 0.10 and
// 0.30 m above the saddle (not sunk into the horse, not floating), and at a steady walk sit exactly in
// the seat (within 1 cm). At the gallop the rider is out of the saddle, the legs taking up the horse's
// bob: the hips leave their seat by at least 3 cm at some moment, so the gallop's seat really plays.
TEST(Cavalry, TheRidersHipsStayOnTheSaddleThroughAWalkToGallopCrossfade) {
    const crowdgpu::Model cavalry = crowdgpu::Model::cavalry(1);
    const model::SkinnedModel& m = cavalry.data()->model;
    const std::uint32_t hips = joint(cavalry, "rider_hips"), saddle = joint(cavalry, "saddle");
    const glm::dvec3 seatFromSaddle = m.skeleton.restPose[hips].translation;
    ASSERT_GT(seatFromSaddle.y, 0.1);

    crowdgpu::Character c;
    c.clip = static_cast<std::uint32_t>(cavalry.findClip("walk"));
    crowdgpu::Crowd crowd({cavalry}, {c}, crowdgpu::Behaviour::InPlace);
    const double fadeAt = 2.0, fade = 0.6;
    crowd.play(0, cavalry.findClip("gallop"), fadeAt, static_cast<float>(fade));
    double walkWorst = 0.0, worst = 0.0, lowest = 1e9, highest = -1e9, gallopMost = 0.0;
    for (int frame = 0; frame <= 4 * 60; ++frame) {
        const double t = frame / 60.0;
        crowd.advanceTo(t);
        float saddleRows[12], hipsRows[12];
        crowd.jointWorld(0, saddle, t, saddleRows);
        crowd.jointWorld(0, hips, t, hipsRows);
        const glm::dvec3 hipsAt = column(hipsRows, 3), saddleAt = column(saddleRows, 3);
        const double fromSeat = glm::length(hipsAt - apply(saddleRows, seatFromSaddle));
        // Height above the saddle along its own up axis.
        const double above = glm::dot(hipsAt - saddleAt, glm::normalize(column(saddleRows, 1)));
        worst = std::max(worst, fromSeat);
        lowest = std::min(lowest, above), highest = std::max(highest, above);
        if (t < fadeAt) walkWorst = std::max(walkWorst, fromSeat);
        if (t > fadeAt + fade) gallopMost = std::max(gallopMost, fromSeat);
    }
    EXPECT_LE(worst, 0.12);
    EXPECT_LE(walkWorst, 0.01);
    EXPECT_GE(gallopMost, 0.03);
    EXPECT_GE(lowest, 0.10);
    EXPECT_LE(highest, 0.30);
    std::printf("hips from seat: walk %.4f m, worst %.4f m, gallop most %.4f m; above the saddle %.3f..%.3f m\n",
                walkWorst, worst, gallopMost, lowest, highest);
}

// The rider's mesh sits on the horse's back, neither sunk into it nor floating, at every phase of both
// gaits (Model::pose: the double-precision CPU skinning the GPU methods match): the lowest vertex the
// rider's hips carry is within 4 cm of the top of the horse's back beneath it at a walk, and rises out
// of the saddle by at most 12 cm at a gallop.
TEST(Cavalry, TheRiderSitsOnTheHorsesBackNeitherSunkNorFloating) {
    const crowdgpu::Model cavalry = crowdgpu::Model::cavalry(1), horse = crowdgpu::Model::horse(1);
    const model::SkinnedModel& m = cavalry.data()->model;
    const std::uint32_t hips = joint(cavalry, "rider_hips");
    for (const char* clipName : {"walk", "gallop"}) {
        const auto clip = static_cast<std::uint32_t>(cavalry.findClip(clipName));
        double lowestGap = 1e9, highestGap = -1e9;
        for (int k = 0; k < 12; ++k) {
            const std::vector<crowdgpu::Model::PosedVertex> posed = cavalry.pose(clip, cavalry.clipDuration(clip) * k / 12.0f);
            // The seat: the lowest vertex mostly carried by the rider's hips.
            std::size_t seat = 0;
            double seatY = 1e9;
            for (std::size_t v = 0; v < posed.size(); ++v)
                if (m.vertices[v].joints.x == hips && m.vertices[v].weights.x >= 0.5f && posed[v].position[1] < seatY)
                    seat = v, seatY = posed[v].position[1];
            // The horse's back beneath it: its highest vertex within 10 cm across.
            double backY = -1e9;
            for (std::size_t v = 0; v < posed.size(); ++v) {
                if (m.vertices[v].joints.x >= horse.jointCount()) continue;
                if (std::hypot(posed[v].position[0] - posed[seat].position[0], posed[v].position[2] - posed[seat].position[2]) < 0.10)
                    backY = std::max(backY, posed[v].position[1]);
            }
            ASSERT_GT(backY, 1.0) << "the horse's back is under the seat";
            lowestGap = std::min(lowestGap, seatY - backY), highestGap = std::max(highestGap, seatY - backY);
        }
        std::printf("%s: seat above the horse's back by %.3f..%.3f m\n", clipName, lowestGap, highestGap);
        EXPECT_GE(lowestGap, -0.04) << clipName << ": sunk into the horse";
        EXPECT_LE(highestGap, std::string(clipName) == "walk" ? 0.04 : 0.12) << clipName << ": floating";
    }
}

// The behaviours' gaits (crowd/gaits.h) are the horse's for the pair: it walks with "walk" and runs with
// "gallop", as the lone horse, and cavalrymen march beside horses in step, as far, turning together.
TEST(Cavalry, TheBehavioursPickTheHorsesGaitsForThePair) {
    const crowdgpu::Model horse = crowdgpu::Model::horse(1), cavalry = crowdgpu::Model::cavalry(1);
    // A formation of two cavalrymen and two horses, side by side, in step.
    std::vector<crowdgpu::Character> formation(4);
    for (std::uint32_t c = 0; c < 4; ++c) {
        formation[c].model = c % 2;
        formation[c].clip = static_cast<std::uint32_t>(horse.findClip("walk"));
        formation[c].position[0] = 4.0f * static_cast<float>(c);
    }
    crowdgpu::Crowd march({cavalry, horse}, formation, crowdgpu::Behaviour::March);
    const crowd::Crowd& inner = march.data().crowd();
    for (std::uint32_t m = 0; m < 2; ++m) {
        EXPECT_EQ(inner.gaits(m).walk, horse.findClip("walk"));
        EXPECT_EQ(inner.gaits(m).run, horse.findClip("gallop"));
    }
    // Marching, the cavalrymen keep the horses' step and place: the same phase, the same way come.
    for (double t : {0.5, 3.0, 12.0, 30.0}) {
        march.advanceTo(t);
        const crowdgpu::CharacterState horseState = march.stateAt(1, t);
        for (std::uint32_t c : {0u, 2u}) {
            const crowdgpu::CharacterState s = march.stateAt(c, t);
            EXPECT_NEAR(s.phase, horseState.phase, 1e-4) << "character " << c << " at " << t << " s";
            EXPECT_NEAR(s.position[2], horseState.position[2], 1e-3) << "character " << c << " at " << t << " s";
            EXPECT_NEAR(s.heading, horseState.heading, 1e-4) << "character " << c << " at " << t << " s";
        }
    }
}

// A glTF rider (CesiumMan, ../shared/assets; skipped when absent) on the built-in horse: its joints are
// not the soldier's, so it rides in its rest pose with a note; its rest pose (its scene's node above the
// skeleton folded in) is the lone model's moved by one translation, which puts its root joint straight
// above the saddle. A glTF mount without the joint (the Fox) is the one clear error.
TEST(Cavalry, AGltfRiderRidesInItsRestPoseAndAGltfMountNeedsTheJoint) {
    const std::filesystem::path cesium = std::filesystem::path(CROWD_SHARED_ASSETS_DIR) / "cesium-man/CesiumMan.glb";
    const std::filesystem::path fox = std::filesystem::path(CROWD_SHARED_ASSETS_DIR) / "fox/Fox.glb";
    if (!std::filesystem::exists(cesium) || !std::filesystem::exists(fox))
        GTEST_SKIP() << "shared assets not present (see ../shared/assets/INVENTORY.md)";
    const crowdgpu::Model horse = crowdgpu::Model::horse(1), rider = crowdgpu::Model::fromGltf(cesium.string());
    const crowdgpu::Model pair = crowdgpu::Model::mounted(horse, rider);
    ASSERT_FALSE(pair.notes().empty());
    EXPECT_NE(pair.notes().back().find("rides in its rest pose"), std::string::npos) << pair.notes().back();
    EXPECT_EQ(pair.vertexCount(), horse.vertexCount() + rider.vertexCount());

    // Rest poses (a clip past the last): the rider's part of the pair against the lone rider, as bounds.
    auto bounds = [](const std::vector<crowdgpu::Model::PosedVertex>& posed, auto keep) {
        glm::dvec3 lo(1e30), hi(-1e30);
        for (std::size_t v = 0; v < posed.size(); ++v) {
            if (!keep(v)) continue;
            const glm::dvec3 p(posed[v].position[0], posed[v].position[1], posed[v].position[2]);
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        return std::pair{lo, hi};
    };
    const model::SkinnedModel& m = pair.data()->model;
    const auto [pairLo, pairHi] = bounds(pair.pose(pair.clipCount(), 0.0f),
                                         [&](std::size_t v) { return m.vertices[v].joints.x >= horse.jointCount(); });
    const auto [aloneLo, aloneHi] = bounds(rider.pose(rider.clipCount(), 0.0f), [](std::size_t) { return true; });
    const glm::dvec3 shift = pairLo - aloneLo;
    EXPECT_LE(glm::length(pairHi - aloneHi - shift), 1e-4) << "moved by one translation";
    EXPECT_GT(glm::length(shift), 0.5) << "and moved up onto the horse";

    try {
        crowdgpu::Model::mounted(crowdgpu::Model::fromGltf(fox.string()), rider);
        ADD_FAILURE() << "the Fox has no saddle joint";
    } catch (const crowdgpu::Error& e) {
        EXPECT_EQ(e.code(), crowdgpu::ErrorCode::InvalidArgument);
        EXPECT_NE(std::string(e.what()).find("no joint 'saddle'"), std::string::npos) << e.what();
    }
}

// A pair with more materials than a model may have (MAX_MODEL_MATERIALS) is refused naming both models.
TEST(Cavalry, MoreMaterialsThanAModelHasIsOneClearError) {
    model::SkinnedModel horse = model::makeHorse(1), soldier = model::makeSoldier(1);
    soldier.materialColors.resize(MAX_MODEL_MATERIALS - horse.materialColors.size() + 1, glm::vec4(1.0f));
    try {
        model::mountRider(horse, soldier, "saddle", "too many", nullptr);
        ADD_FAILURE() << "17 materials accepted";
    } catch (const gpu::Error& e) {
        EXPECT_EQ(e.kind(), gpu::ErrorKind::InvalidArgument);
        EXPECT_EQ(std::string(e.what()), "horse and soldier: 17 materials together, more than a model has (16)");
    }
    soldier.materialColors.pop_back();
    EXPECT_EQ(model::mountRider(horse, soldier, "saddle", "just enough", nullptr).materialColors.size(), 16u);
}
