// Joint queries (crowdgpu::Crowd::jointWorld): a joint's world transform against the skinned mesh.
// A vertex skinned to one joint only sits at world joint x inverse bind x bind position; the reference
// is Model::pose (double-precision skinning of the clip at that time, independent of the crowd's jobs)
// placed where stateAt puts the character.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "api/api_data.h"
#include "crowdgpu/crowd.hpp"
#include "crowdgpu/error.hpp"
#include "crowdgpu/model.hpp"

namespace {

// Rows of a 3x4 matrix applied to a point.
glm::dvec3 apply(const float rows[12], const glm::dvec3& p) {
    glm::dvec3 r;
    for (int i = 0; i < 3; ++i) r[i] = rows[4 * i] * p.x + rows[4 * i + 1] * p.y + rows[4 * i + 2] * p.z + rows[4 * i + 3];
    return r;
}

// The character's placement of a model-space point, by hand: scale, turn about +y, translate.
glm::dvec3 place(const crowdgpu::CharacterState& s, double scale, const glm::dvec3& p) {
    const double c = std::cos(s.heading), sn = std::sin(s.heading);
    const glm::dvec3 q = scale * p;
    return {c * q.x + sn * q.z + s.position[0], q.y + s.position[1], -sn * q.x + c * q.z + s.position[2]};
}

TEST(JointQueries, HandJointCarriesTheVerticesSkinnedToItInWalkingAndMillingCrowds) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1);
    const std::int32_t hand = soldier.findJoint("hand_r");
    ASSERT_GE(hand, 0);
    EXPECT_EQ(soldier.jointName(static_cast<std::uint32_t>(hand)), "hand_r");
    const model::SkinnedModel& m = soldier.data()->model;
    // Vertices weighted fully to the hand.
    std::vector<std::uint32_t> handVertices;
    for (std::uint32_t v = 0; v < m.vertices.size(); ++v)
        if (m.vertices[v].joints.x == static_cast<std::uint32_t>(hand) && m.vertices[v].weights.x == 1.0f)
            handVertices.push_back(v);
    ASSERT_GE(handVertices.size(), 4u);
    const glm::mat4& inverseBind = m.skeleton.inverseBind[static_cast<std::size_t>(hand)];

    for (const crowdgpu::Behaviour behaviour : {crowdgpu::Behaviour::InPlace, crowdgpu::Behaviour::Mill}) {
        crowdgpu::GridLayout layout;
        layout.count = 9;
        layout.seed = 3;
        layout.scaleVariation = 0.1f;
        crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, behaviour);
        int compared = 0;
        for (double t : {0.0, 0.37, 2.5, 7.25, 19.9, 41.3}) {
            crowd.advanceTo(t);
            for (std::uint32_t c = 0; c < crowd.size(); ++c) {
                const crowdgpu::CharacterState s = crowd.stateAt(c, t);
                if (s.weight < 1.0f) continue;  // Model::pose skins one clip: compare between crossfades
                float rows[12];
                crowd.jointWorld(c, static_cast<std::uint32_t>(hand), t, rows);
                const float cycle = s.phase - std::floor(s.phase);
                const std::vector<crowdgpu::Model::PosedVertex> posed =
                    soldier.pose(s.clipTo, cycle * soldier.clipDuration(s.clipTo));
                const double scale = crowd.character(c).scale;
                for (const std::uint32_t v : handVertices) {
                    const glm::vec4 local = inverseBind * m.vertices[v].position;
                    const glm::dvec3 fromQuery = apply(rows, glm::dvec3(local));
                    const glm::dvec3 expected =
                        place(s, scale, {posed[v].position[0], posed[v].position[1], posed[v].position[2]});
                    EXPECT_LT(glm::length(fromQuery - expected), 1e-3)
                        << "character " << c << " at " << t << " s, vertex " << v;
                }
                ++compared;
            }
        }
        EXPECT_GT(compared, 30) << crowdgpu::behaviourName(behaviour);
    }
}

TEST(JointQueries, BadCharacterJointOrTimeIsInvalidArgument) {
    const crowdgpu::Model soldier = crowdgpu::Model::soldier(1);
    EXPECT_EQ(soldier.findJoint("tail"), -1);
    crowdgpu::GridLayout layout;
    layout.count = 4;
    crowdgpu::Crowd crowd = crowdgpu::Crowd::grid({soldier}, layout, crowdgpu::Behaviour::Mill);
    crowd.advanceTo(1.0);
    float rows[12];
    auto code = [&](auto&& call) {
        try {
            call();
        } catch (const crowdgpu::Error& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
            return e.code();
        }
        return static_cast<crowdgpu::ErrorCode>(0);
    };
    EXPECT_EQ(code([&] { crowd.jointWorld(4, 0, 1.0, rows); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { crowd.jointWorld(0, soldier.jointCount(), 1.0, rows); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { soldier.jointName(soldier.jointCount()); }), crowdgpu::ErrorCode::InvalidArgument);
    // Long after the start every milling character has replanned more than once: the start is forgotten.
    crowd.advanceTo(600.0);
    EXPECT_EQ(code([&] { crowd.jointWorld(0, 0, 0.5, rows); }), crowdgpu::ErrorCode::InvalidArgument);
    EXPECT_EQ(code([&] { crowd.jointWorld(0, 0, 600.0, rows); }), static_cast<crowdgpu::ErrorCode>(0));
}

}  // namespace
