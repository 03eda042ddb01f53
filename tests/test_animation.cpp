// Animation jobs against hand-computed poses.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "anim/local_to_model.h"
#include "anim/skeleton.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"

namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec4 quatXYZW(float angle, glm::vec3 axis) {
    const glm::quat q = glm::angleAxis(angle, glm::normalize(axis));
    return {q.x, q.y, q.z, q.w};
}

// A two-joint arm: root at the origin, elbow 1 m along +x.
anim::Skeleton twoJointArm() {
    anim::Skeleton s;
    s.jointNames = {"shoulder", "elbow"};
    s.parents = {-1, 0};
    s.restPose.resize(2);
    s.restPose[1].translation = {1, 0, 0};
    s.inverseBind = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0))};
    return s;
}

anim::Clip rotateShoulderAboutZ(float degreesAtEnd, anim::Interpolation interpolation) {
    anim::Clip clip;
    clip.name = "raise";
    clip.duration = 1.0f;
    anim::Channel channel;
    channel.joint = 0;
    channel.path = anim::ChannelPath::Rotation;
    channel.interpolation = interpolation;
    channel.times = {0.0f, 1.0f};
    channel.values = {quatXYZW(0.0f, {0, 0, 1}), quatXYZW(glm::radians(degreesAtEnd), {0, 0, 1})};
    clip.channels.push_back(channel);
    return clip;
}

}  // namespace

TEST(Animation, HierarchyRotatesChildAboutParent) {
    const anim::Skeleton arm = twoJointArm();
    std::vector<anim::Transform> locals = arm.restPose;
    locals[0].rotation = glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1));
    std::vector<glm::mat4> model(2);
    anim::localToModel(arm.parents, locals, glm::mat4(1.0f), model);
    // The elbow, 1 m along x, swings to 1 m along y.
    const glm::vec3 elbow = model[1] * glm::vec4(0, 0, 0, 1);
    EXPECT_NEAR(elbow.x, 0.0f, 1e-6f);
    EXPECT_NEAR(elbow.y, 1.0f, 1e-6f);
}

TEST(Animation, RestPoseGivesIdentitySkinningMatrices) {
    const anim::Skeleton arm = twoJointArm();
    std::vector<glm::mat4> model(2);
    anim::localToModel(arm.parents, arm.restPose, glm::mat4(1.0f), model);
    std::vector<gpu::BoneRows> rows(2);
    anim::skinningMatrices(model, arm.inverseBind, glm::mat4(1.0f), rows);
    for (const gpu::BoneRows& r : rows) {
        const glm::mat4 m = anim::fromRows(r);
        for (int c = 0; c < 4; ++c)
            for (int i = 0; i < 4; ++i) EXPECT_NEAR(m[c][i], c == i ? 1.0f : 0.0f, 1e-6f);
    }
}

TEST(Animation, SkinningMatrixMovesBindVertexWithItsJoint) {
    // A vertex at the hand (2 m along x) bound to the elbow; the shoulder turns 90 degrees about z
    // and the crowd places the character 5 m along z: the vertex lands at (0, 2, 5).
    const anim::Skeleton arm = twoJointArm();
    std::vector<anim::Transform> locals = arm.restPose;
    locals[0].rotation = glm::angleAxis(kPi / 2, glm::vec3(0, 0, 1));
    std::vector<glm::mat4> model(2);
    anim::localToModel(arm.parents, locals, glm::mat4(1.0f), model);
    std::vector<gpu::BoneRows> rows(2);
    anim::skinningMatrices(model, arm.inverseBind, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)), rows);
    const glm::vec4 p = anim::fromRows(rows[1]) * glm::vec4(2, 0, 0, 1);
    EXPECT_NEAR(p.x, 0.0f, 1e-5f);
    EXPECT_NEAR(p.y, 2.0f, 1e-5f);
    EXPECT_NEAR(p.z, 5.0f, 1e-5f);
}

TEST(Animation, LinearRotationIsSlerpHalfway) {
    const anim::Skeleton arm = twoJointArm();
    const anim::Clip clip = rotateShoulderAboutZ(90.0f, anim::Interpolation::Linear);
    std::vector<anim::Transform> out(2);
    anim::sampleClip(clip, 0.5f, arm.restPose, out);
    const glm::quat expected = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
    EXPECT_NEAR(std::abs(glm::dot(out[0].rotation, expected)), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(out[0].rotation), 1.0f, 1e-6f);
}

TEST(Animation, SlerpTakesTheShorterArc) {
    // Keys q and -q' that are 20 degrees apart the short way: halfway must be 10 degrees, not 170.
    anim::Clip clip = rotateShoulderAboutZ(20.0f, anim::Interpolation::Linear);
    clip.channels[0].values[1] = -clip.channels[0].values[1];
    std::vector<anim::Transform> out(2);
    anim::sampleClip(clip, 0.5f, twoJointArm().restPose, out);
    const glm::quat expected = glm::angleAxis(glm::radians(10.0f), glm::vec3(0, 0, 1));
    EXPECT_NEAR(std::abs(glm::dot(out[0].rotation, expected)), 1.0f, 1e-6f);
}

TEST(Animation, StepHoldsTheEarlierKey) {
    const anim::Clip clip = rotateShoulderAboutZ(90.0f, anim::Interpolation::Step);
    std::vector<anim::Transform> out(2);
    anim::sampleClip(clip, 0.99f, twoJointArm().restPose, out);
    EXPECT_NEAR(std::abs(out[0].rotation.w), 1.0f, 1e-6f);
}

TEST(Animation, CubicSplineWithZeroTangentsIsSmoothstep) {
    anim::Clip clip;
    clip.duration = 2.0f;
    anim::Channel channel;
    channel.path = anim::ChannelPath::Translation;
    channel.interpolation = anim::Interpolation::CubicSpline;
    channel.times = {0.0f, 2.0f};
    // (in-tangent, value, out-tangent) per key
    channel.values = {glm::vec4(0), glm::vec4(0), glm::vec4(0), glm::vec4(0), glm::vec4(4, 0, 0, 0), glm::vec4(0)};
    clip.channels.push_back(channel);
    std::vector<anim::Transform> out(1);
    anim::sampleClip(clip, 0.5f, std::vector<anim::Transform>(1), out);
    // s = 0.25: 4 * (3 s^2 - 2 s^3) = 0.625
    EXPECT_NEAR(out[0].translation.x, 0.625f, 1e-6f);
}

TEST(Animation, TimeWrapsSoClipsLoop) {
    EXPECT_NEAR(anim::wrapTime(2.5f, 1.0f), 0.5f, 1e-6f);
    EXPECT_NEAR(anim::wrapTime(-0.25f, 1.0f), 0.75f, 1e-6f);
    EXPECT_EQ(anim::wrapTime(3.0f, 0.0f), 0.0f);
}

TEST(Animation, UnanimatedJointsKeepRestPose) {
    const anim::Skeleton arm = twoJointArm();
    std::vector<anim::Transform> out(2);
    anim::sampleClip(rotateShoulderAboutZ(90.0f, anim::Interpolation::Linear), 0.3f, arm.restPose, out);
    EXPECT_EQ(out[1].translation, glm::vec3(1, 0, 0));
}
