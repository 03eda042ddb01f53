// anim::poseReach and channelReach against poses sampled by the clip's own jobs: the bound holds at
// every sampled time, is exact where it can be, and names the channel that leaves a limit.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "anim/local_to_model.h"
#include "anim/pose_reach.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"

namespace {

anim::Channel channel(std::uint32_t joint, anim::ChannelPath path, anim::Interpolation interpolation,
                      std::vector<float> times, std::vector<glm::vec4> values) {
    anim::Channel c;
    c.joint = joint;
    c.path = path;
    c.interpolation = interpolation;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

anim::Skeleton oneJoint() {
    anim::Skeleton s;
    s.jointNames = {"root"};
    s.parents = {-1};
    s.restPose.resize(1);
    s.inverseBind = {glm::mat4(1.0f)};
    return s;
}

// A chain: root, then a child 1 m along x whose inverse bind undoes that.
anim::Skeleton twoJointChain() {
    anim::Skeleton s;
    s.jointNames = {"root", "child"};
    s.parents = {-1, 0};
    s.restPose.resize(2);
    s.restPose[1].translation = {1, 0, 0};
    s.inverseBind = {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0))};
    return s;
}

// The farthest that `vertices`, each bound wholly to one joint, get from the origin over `samples`
// times of the clip: the clip's own jobs, evaluated in double from their float matrices.
double sampledReach(const anim::Skeleton& skeleton, const anim::Clip& clip,
                    const std::vector<std::pair<std::uint32_t, glm::vec3>>& vertices, int samples) {
    std::vector<anim::Transform> locals(skeleton.jointCount());
    std::vector<glm::mat4> model(skeleton.jointCount());
    double reach = 0.0;
    for (int i = 0; i < samples; ++i) {  // the clip loops: its duration is time 0 again
        anim::sampleClip(clip, clip.duration * static_cast<float>(i) / static_cast<float>(samples), skeleton.restPose,
                         locals);
        anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, model);
        for (const auto& [joint, position] : vertices) {
            const glm::dvec4 p = glm::dmat4(model[joint] * skeleton.inverseBind[joint]) * glm::dvec4(position, 1.0);
            reach = std::max(reach, glm::length(glm::dvec3(p)));
        }
    }
    return reach;
}

}  // namespace

TEST(PoseReach, OneTranslatedJointReachesItsFarthestKeyPlusTheFarthestVertex) {
    // Keys (0,0,0), (3,4,0), (0,0,0): 5 m at 0.5 s; a vertex 2 m from the origin along the same
    // direction gets 7 m away.
    anim::Clip clip;
    clip.duration = 1.0f;
    clip.channels = {channel(0, anim::ChannelPath::Translation, anim::Interpolation::Linear, {0.0f, 0.5f, 1.0f},
                             {glm::vec4(0.0f), glm::vec4(3, 4, 0, 0), glm::vec4(0.0f)})};
    const anim::PoseReach reach = anim::poseReach(oneJoint(), clip, 2.0, 1e18);
    EXPECT_NEAR(reach.distance, 7.0, 1e-7);
    EXPECT_EQ(reach.channel, -1);
    EXPECT_NEAR(sampledReach(oneJoint(), clip, {{0, glm::vec3(1.2f, 1.6f, 0.0f)}}, 10), 7.0, 1e-5);
}

TEST(PoseReach, BoundsEverySampledPoseOfAScaledRotatedChain) {
    anim::Skeleton chain = twoJointChain();
    chain.rootTransform = glm::rotate(glm::scale(glm::mat4(1.0f), glm::vec3(2, 1, 1)), 0.7f, glm::vec3(0, 1, 0));
    anim::Clip clip;
    clip.duration = 2.0f;
    clip.channels = {
        channel(0, anim::ChannelPath::Scale, anim::Interpolation::Linear, {0.0f, 1.0f, 2.0f},
                {glm::vec4(1, 1, 1, 0), glm::vec4(3, 0.5f, 1, 0), glm::vec4(1, 1, 1, 0)}),
        channel(1, anim::ChannelPath::Rotation, anim::Interpolation::Linear, {0.0f, 2.0f},
                {glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, std::sin(1.0f), std::cos(1.0f))}),
        channel(1, anim::ChannelPath::Translation, anim::Interpolation::Step, {0.0f, 1.5f},
                {glm::vec4(1, 0, 0, 0), glm::vec4(0, 2, 0, 0)}),
    };
    const std::vector<std::pair<std::uint32_t, glm::vec3>> vertices = {
        {0, {0.5f, 0.0f, 0.0f}}, {1, {1.5f, 0.3f, 0.0f}}, {1, {1.0f, -0.5f, 0.4f}}};
    const double sampled = sampledReach(chain, clip, vertices, 400);
    const double bound = anim::poseReach(chain, clip, glm::length(glm::vec3(1.5f, 0.3f, 0.0f)), 1e18).distance;
    EXPECT_GE(bound, sampled * (1.0 - 1e-6));
    EXPECT_LT(bound, 10.0 * sampled) << "a bound this loose would refuse real characters";
}

TEST(PoseReach, CubicSplineOvershootIsCovered) {
    // From 0 to 1 m with steep tangents: the curve overshoots past both keys.
    anim::Clip clip;
    clip.duration = 1.0f;
    clip.channels = {channel(0, anim::ChannelPath::Translation, anim::Interpolation::CubicSpline, {0.0f, 1.0f},
                             {glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(-10, 0, 0, 0),  // in, value, out
                              glm::vec4(-10, 0, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(0.0f)})};
    const double sampled = sampledReach(oneJoint(), clip, {{0, glm::vec3(0.0f)}}, 1000);
    EXPECT_GT(sampled, 1.2);  // the overshoot is real
    EXPECT_GE(anim::channelReach(clip.channels[0]), sampled * (1.0 - 1e-6));
    EXPECT_NEAR(anim::channelReach(clip.channels[0]), 1.0 + 4.0 / 27.0 * 20.0, 1e-9);
}

TEST(PoseReach, NamesTheFirstChannelThatTakesPosesBeyondTheLimit) {
    // Each scale alone stays within 1e15; the root's and the child's together multiply past it.
    anim::Clip clip;
    clip.duration = 1.0f;
    const glm::vec4 big(1e10f, 1e10f, 1e10f, 0.0f);
    clip.channels = {
        channel(1, anim::ChannelPath::Rotation, anim::Interpolation::Step, {0.0f}, {glm::vec4(0, 0, 0, 1)}),
        channel(0, anim::ChannelPath::Scale, anim::Interpolation::Step, {0.0f}, {big}),
        channel(1, anim::ChannelPath::Scale, anim::Interpolation::Step, {0.0f}, {big}),
    };
    const anim::PoseReach reach = anim::poseReach(twoJointChain(), clip, 1.0, 1e15);
    EXPECT_EQ(reach.channel, 2);
    EXPECT_GT(reach.distance, 1e20);
    clip.channels.pop_back();
    EXPECT_EQ(anim::poseReach(twoJointChain(), clip, 1.0, 1e15).channel, -1);
    EXPECT_LE(anim::poseReach(twoJointChain(), clip, 1.0, 1e15).distance, 1e15);
}

TEST(PoseReach, FloatLimitKeysReachInfinityAndARestPoseBeyondTheLimitNamesNoChannel) {
    anim::Clip clip;
    clip.duration = 1.0f;
    const glm::vec4 nearMax(3e38f, 3e38f, 3e38f, 0.0f);  // finite; squared or multiplied, not
    clip.channels = {channel(0, anim::ChannelPath::Translation, anim::Interpolation::Linear, {0.0f, 1.0f},
                             {nearMax, -nearMax})};
    const anim::PoseReach reach = anim::poseReach(oneJoint(), clip, 1.0, 1e18);
    EXPECT_EQ(reach.channel, 0);
    EXPECT_GT(reach.distance, 1e38);

    anim::Skeleton huge = oneJoint();
    huge.restPose[0].scale = glm::vec3(1e20f);
    const anim::PoseReach rest = anim::poseReach(huge, anim::Clip{}, 1.0, 1e18);
    EXPECT_EQ(rest.channel, -1);
    EXPECT_GT(rest.distance, 1e18);
}

TEST(Animation, CubicSplineRotationThroughZeroStaysAUnitQuaternion) {
    // Opposite keys (q and -q are the same rotation) with zero tangents: halfway the spline is the
    // zero quaternion, which has no direction. The sampler must still give a rotation.
    anim::Clip clip;
    clip.duration = 1.0f;
    clip.channels = {channel(0, anim::ChannelPath::Rotation, anim::Interpolation::CubicSpline, {0.0f, 1.0f},
                             {glm::vec4(0.0f), glm::vec4(0, 0, 0.6f, 0.8f), glm::vec4(0.0f),  //
                              glm::vec4(0.0f), glm::vec4(0, 0, -0.6f, -0.8f), glm::vec4(0.0f)})};
    std::vector<anim::Transform> pose(1);
    anim::sampleClip(clip, 0.5f, oneJoint().restPose, pose);
    const glm::quat q = pose[0].rotation;
    ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w));
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(q.z), 0.6f, 1e-6f);  // the keys' own rotation
}
