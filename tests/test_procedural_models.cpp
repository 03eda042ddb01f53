// The built-in soldier and horse: mesh, rig and clips are well formed, and they move like a
// soldier and a horse (checked on the CPU through the same animation jobs the renderer uses).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"
#include "model/mounted_model.h"
#include "model/procedural_models.h"

namespace {

using model::SkinnedModel;

// ---- CPU reference: pose a model and skin its vertices ------------------------------------------

std::vector<anim::Transform> sampledPose(const SkinnedModel& m, const std::string& clip, float time) {
    std::vector<anim::Transform> locals(m.skeleton.jointCount());
    anim::sampleClip(m.clips[static_cast<std::size_t>(m.findClip(clip))], time, m.skeleton.restPose, locals);
    return locals;
}

std::vector<glm::mat4> modelMatrices(const SkinnedModel& m, const std::vector<anim::Transform>& locals) {
    std::vector<glm::mat4> global(locals.size());
    anim::localToModel(m.skeleton.parents, locals, m.skeleton.rootTransform, global);
    return global;
}

// Skins with the 3x4 rows the GPU reads, blending the rows by the vertex weights.
std::vector<glm::vec3> skinnedPositions(const SkinnedModel& m, const std::vector<anim::Transform>& locals) {
    std::vector<gpu::BoneRows> rows(locals.size());
    anim::skinningMatrices(modelMatrices(m, locals), m.skeleton.inverseBind, glm::mat4(1.0f), rows);
    std::vector<glm::vec3> out;
    out.reserve(m.vertices.size());
    for (const gpu::SkinVertex& v : m.vertices) {
        glm::vec3 p(0.0f);
        for (int k = 0; k < 4; ++k) {
            const gpu::BoneRows& r = rows[v.joints[k]];
            p += v.weights[k] * glm::vec3(glm::dot(r.row0, v.position), glm::dot(r.row1, v.position),
                                          glm::dot(r.row2, v.position));
        }
        out.push_back(p);
    }
    return out;
}

std::vector<glm::vec3> skinnedAt(const SkinnedModel& m, const std::string& clip, float time) {
    return skinnedPositions(m, sampledPose(m, clip, time));
}

float largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, glm::distance(a[i], b[i]));
    return largest;
}

std::uint32_t jointNamed(const SkinnedModel& m, const std::string& name) {
    const auto& names = m.skeleton.jointNames;
    const auto it = std::find(names.begin(), names.end(), name);
    EXPECT_NE(it, names.end()) << name;
    return static_cast<std::uint32_t>(it - names.begin());
}

glm::vec3 jointPosition(const std::vector<glm::mat4>& global, std::uint32_t joint) {
    return glm::vec3(global[joint][3]);
}

// The joint with the largest weight on a vertex.
std::uint32_t dominantJoint(const gpu::SkinVertex& v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
        if (v.weights[k] > v.weights[best]) best = k;
    return v.joints[best];
}

glm::vec3 bindPosition(const gpu::SkinVertex& v) { return glm::vec3(v.position); }

// ---- Properties both characters share ----------------------------------------------------------

struct Character {
    std::string name;
    SkinnedModel (*make)(std::uint32_t seed);
    std::size_t minJoints, maxJoints;
    std::size_t minTriangles, maxTriangles;
    std::vector<std::string> clipNames;
    // Joints that bend (with their parents) where the skin must blend rather than tear.
    std::vector<std::string> bendingJoints;
};

std::ostream& operator<<(std::ostream& os, const Character& c) { return os << c.name; }

// With its props (a rifle and a flag: two joints and 96 triangles more than the body's 1,020).
SkinnedModel makeSoldierWithProps(std::uint32_t seed) { return model::makeSoldier(seed); }

const Character kSoldier{"soldier", &makeSoldierWithProps, 20, 30,
                         // The paper's soldier has 1,084 triangles; allow 10 % either way.
                         975, 1192, {"idle", "walk", "run"},
                         {"spine", "chest", "forearm_l", "forearm_r", "shin_l", "shin_r", "toe_l"}};
const Character kHorse{"horse", &model::makeHorse, 20, 35, 1000, 2000, {"walk", "gallop"},
                       {"spine", "neck_upper", "front_cannon_l", "hind_cannon_r", "tail_2"}};
// The soldier on the horse (docs/cavalry.md): both skeletons and meshes, the horse's clips.
const Character kCavalry{"cavalry", &model::makeCavalry, 40, 65, 2000, 3200, {"walk", "gallop"},
                         {"spine", "front_cannon_l", "rider_chest", "rider_forearm_r", "rider_shin_l"}};

class ProceduralModel : public testing::TestWithParam<Character> {
protected:
    // Built once per test: generation takes milliseconds.
    const SkinnedModel m = GetParam().make(1);
};

TEST_P(ProceduralModel, IsNamedAfterTheCharacter) { EXPECT_EQ(m.name, GetParam().name); }

TEST_P(ProceduralModel, JointCountIsInRange) {
    EXPECT_GE(m.skeleton.jointCount(), GetParam().minJoints);
    EXPECT_LE(m.skeleton.jointCount(), GetParam().maxJoints);
    EXPECT_EQ(m.skeleton.jointNames.size(), m.skeleton.jointCount());
    EXPECT_EQ(m.skeleton.restPose.size(), m.skeleton.jointCount());
    EXPECT_EQ(m.skeleton.inverseBind.size(), m.skeleton.jointCount());
}

TEST_P(ProceduralModel, ParentsComeBeforeChildrenUnderOneRoot) {
    const auto& parents = m.skeleton.parents;
    ASSERT_FALSE(parents.empty());
    EXPECT_EQ(parents[0], -1);
    for (std::size_t i = 1; i < parents.size(); ++i) {
        EXPECT_GE(parents[i], 0) << "joint " << i << " is a second root";
        EXPECT_LT(parents[i], static_cast<std::int32_t>(i));
    }
    EXPECT_EQ(m.skeleton.rootTransform, glm::mat4(1.0f));
}

TEST_P(ProceduralModel, TriangleCountIsInRange) {
    EXPECT_EQ(m.indices.size() % 3, 0u);
    EXPECT_GE(m.triangleCount(), GetParam().minTriangles);
    EXPECT_LE(m.triangleCount(), GetParam().maxTriangles);
}

TEST_P(ProceduralModel, IndicesAddressVertices) {
    for (std::uint32_t index : m.indices) ASSERT_LT(index, m.vertices.size());
}

TEST_P(ProceduralModel, WeightsAreNormalizedOverValidJoints) {
    for (const gpu::SkinVertex& v : m.vertices) {
        float sum = 0.0f;
        for (int k = 0; k < 4; ++k) {
            ASSERT_GE(v.weights[k], 0.0f);
            ASSERT_LT(v.joints[k], m.skeleton.jointCount());
            if (v.weights[k] == 0.0f) {
                ASSERT_EQ(v.joints[k], 0u) << "unused slots point at joint 0";
            }
            sum += v.weights[k];
        }
        ASSERT_NEAR(sum, 1.0f, 1e-6f);
    }
}

// Smooth skinning: round every bending joint some vertices follow both the joint and its parent.
TEST_P(ProceduralModel, SkinBlendsAcrossBendingJoints) {
    for (const std::string& name : GetParam().bendingJoints) {
        const std::uint32_t child = jointNamed(m, name);
        const std::uint32_t parent = static_cast<std::uint32_t>(m.skeleton.parents[child]);
        std::size_t blended = 0;
        for (const gpu::SkinVertex& v : m.vertices) {
            float onChild = 0.0f, onParent = 0.0f;
            for (int k = 0; k < 4; ++k) {
                if (v.joints[k] == child) onChild += v.weights[k];
                if (v.joints[k] == parent) onParent += v.weights[k];
            }
            if (onChild > 0.2f && onParent > 0.2f) ++blended;
        }
        EXPECT_GE(blended, 4u) << name << " is a hard cut";
    }
}

TEST_P(ProceduralModel, NormalsAreUnitLength) {
    for (const gpu::SkinVertex& v : m.vertices) ASSERT_NEAR(glm::length(glm::vec3(v.normal)), 1.0f, 1e-4f);
}

TEST_P(ProceduralModel, MaterialIndicesAreWholeNumbersIntoAPalette) {
    ASSERT_FALSE(m.materialColors.empty());
    EXPECT_LE(m.materialColors.size(), static_cast<std::size_t>(MAX_MODEL_MATERIALS));
    for (const glm::vec4& c : m.materialColors) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, glm::vec4(0.0f))));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(c, glm::vec4(1.0f))));
    }
    for (const gpu::SkinVertex& v : m.vertices) {
        ASSERT_EQ(v.normal.w, std::floor(v.normal.w));
        ASSERT_LT(static_cast<std::size_t>(v.normal.w), m.materialColors.size());
        ASSERT_EQ(v.position.w, 1.0f);
    }
}

TEST_P(ProceduralModel, FacesAgreeWithTheirVertexNormals) {
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const gpu::SkinVertex& a = m.vertices[m.indices[t]];
        const gpu::SkinVertex& b = m.vertices[m.indices[t + 1]];
        const gpu::SkinVertex& c = m.vertices[m.indices[t + 2]];
        const glm::vec3 face = glm::cross(bindPosition(b) - bindPosition(a), bindPosition(c) - bindPosition(a));
        const glm::vec3 normals = glm::vec3(a.normal) + glm::vec3(b.normal) + glm::vec3(c.normal);
        ASSERT_GT(glm::dot(face, normals), 0.0f) << "triangle " << t / 3;
    }
}

// Vertex normals alone cannot show the winding is outward (both could be flipped together), so
// weld the parts by position and check each is closed, consistently wound and of positive volume.
TEST_P(ProceduralModel, EveryPartIsClosedAndWoundOutward) {
    std::map<std::array<float, 3>, std::uint32_t> weldIds;
    std::vector<std::uint32_t> welded;
    for (const gpu::SkinVertex& v : m.vertices) {
        const std::array<float, 3> key = {v.position.x, v.position.y, v.position.z};
        welded.push_back(weldIds.try_emplace(key, static_cast<std::uint32_t>(weldIds.size())).first->second);
    }
    std::vector<std::uint32_t> part(weldIds.size());
    std::iota(part.begin(), part.end(), 0u);
    auto root = [&part](std::uint32_t i) {
        while (part[i] != i) i = part[i] = part[part[i]];
        return i;
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t from = welded[m.indices[t + e]], to = welded[m.indices[t + (e + 1) % 3]];
            ++directedEdges[{from, to}];
            part[root(from)] = root(to);
        }
    }
    for (const auto& [edge, count] : directedEdges) {
        ASSERT_EQ(count, 1) << "edge used twice in one direction: a flipped triangle";
        ASSERT_EQ(directedEdges.count({edge.second, edge.first}), 1u) << "open edge";
    }
    std::map<std::uint32_t, double> volumes;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a = bindPosition(m.vertices[m.indices[t]]), b = bindPosition(m.vertices[m.indices[t + 1]]),
                         c = bindPosition(m.vertices[m.indices[t + 2]]);
        volumes[root(welded[m.indices[t]])] += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    EXPECT_GE(volumes.size(), 5u);
    for (const auto& [id, volume] : volumes) EXPECT_GT(volume, 0.0) << "part " << id << " is inside out";
}

TEST_P(ProceduralModel, InverseBindUndoesTheRestPose) {
    const std::vector<glm::mat4> global = modelMatrices(m, m.skeleton.restPose);
    for (std::size_t j = 0; j < global.size(); ++j) {
        const glm::mat4 skin = global[j] * m.skeleton.inverseBind[j];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(skin[c][r], c == r ? 1.0f : 0.0f, 1e-5f) << "joint " << j;
    }
}

TEST_P(ProceduralModel, RestPoseSkinsToTheBindVertices) {
    const std::vector<glm::vec3> skinned = skinnedPositions(m, m.skeleton.restPose);
    for (std::size_t i = 0; i < skinned.size(); ++i)
        ASSERT_LT(glm::distance(skinned[i], bindPosition(m.vertices[i])), 1e-5f) << "vertex " << i;
}

TEST_P(ProceduralModel, StandsOnTheGroundAtTheOrigin) {
    EXPECT_NEAR(m.boundsMin.y, 0.0f, 0.01f);
    const glm::vec3 center = 0.5f * (m.boundsMin + m.boundsMax);
    EXPECT_NEAR(center.x, 0.0f, 0.01f) << "symmetric about x = 0";
    EXPECT_NEAR(center.z, 0.0f, 0.3f);
}

TEST_P(ProceduralModel, HasExactlyTheNamedClips) {
    ASSERT_EQ(m.clips.size(), GetParam().clipNames.size());
    for (const std::string& name : GetParam().clipNames) {
        const int clip = m.findClip(name);
        ASSERT_GE(clip, 0) << name;
        EXPECT_GT(m.clips[static_cast<std::size_t>(clip)].duration, 0.0f);
        EXPECT_FALSE(m.clips[static_cast<std::size_t>(clip)].channels.empty());
    }
}

TEST_P(ProceduralModel, ChannelsAreClosedLinearLoopsOfUnitQuaternions) {
    for (const anim::Clip& clip : m.clips) {
        for (const anim::Channel& ch : clip.channels) {
            ASSERT_LT(ch.joint, m.skeleton.jointCount());
            EXPECT_EQ(ch.interpolation, anim::Interpolation::Linear);
            ASSERT_EQ(ch.times.size(), ch.values.size());
            EXPECT_GE(ch.times.size(), 25u);
            EXPECT_LE(ch.times.size(), 33u);
            EXPECT_EQ(ch.times.front(), 0.0f);
            EXPECT_FLOAT_EQ(ch.times.back(), clip.duration);
            EXPECT_EQ(std::adjacent_find(ch.times.begin(), ch.times.end(), std::greater_equal<float>()), ch.times.end())
                << "times strictly increase";
            EXPECT_EQ(ch.values.front(), ch.values.back()) << clip.name << ": the loop closes on its first key";
            if (ch.path != anim::ChannelPath::Rotation) continue;
            for (const glm::vec4& q : ch.values) EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
        }
    }
}

TEST_P(ProceduralModel, ClipsLoopWithoutAJump) {
    for (const anim::Clip& clip : m.clips) {
        const auto start = skinnedAt(m, clip.name, 0.0f);
        const auto end = skinnedAt(m, clip.name, clip.duration - 1e-4f);
        // At a few metres per second, 0.1 ms of motion is well under a millimetre.
        EXPECT_LT(largestDistance(start, end), 2e-3f) << clip.name;
    }
}

TEST_P(ProceduralModel, ClipsMoveThroughDifferentPoses) {
    for (const anim::Clip& clip : m.clips) {
        const auto a = skinnedAt(m, clip.name, 0.0f);
        // A quarter loop apart: half a loop could be a gait's mirror image, a quarter never is.
        const auto b = skinnedAt(m, clip.name, 0.25f * clip.duration);
        EXPECT_GT(largestDistance(a, b), clip.name == "idle" ? 0.01f : 0.1f) << clip.name;
    }
}

TEST_P(ProceduralModel, ClipsAnimateInPlace) {
    const std::uint32_t root = 0;
    for (const anim::Clip& clip : m.clips) {
        for (int s = 0; s < 16; ++s) {
            const auto locals = sampledPose(m, clip.name, clip.duration * static_cast<float>(s) / 16.0f);
            const glm::vec3 moved = locals[root].translation - m.skeleton.restPose[root].translation;
            EXPECT_LT(std::hypot(moved.x, moved.z), 0.05f) << clip.name << ": no root motion";
        }
    }
}

TEST_P(ProceduralModel, SameSeedGivesIdenticalModels) {
    const SkinnedModel again = GetParam().make(1);
    ASSERT_EQ(again.vertices.size(), m.vertices.size());
    EXPECT_EQ(std::memcmp(again.vertices.data(), m.vertices.data(), m.vertices.size() * sizeof(gpu::SkinVertex)), 0);
    EXPECT_EQ(again.indices, m.indices);
    ASSERT_EQ(again.clips.size(), m.clips.size());
    for (std::size_t c = 0; c < m.clips.size(); ++c) {
        ASSERT_EQ(again.clips[c].channels.size(), m.clips[c].channels.size());
        for (std::size_t k = 0; k < m.clips[c].channels.size(); ++k)
            EXPECT_EQ(again.clips[c].channels[k].values, m.clips[c].channels[k].values);
    }
}

TEST_P(ProceduralModel, SeedsVaryProportionsSlightly) {
    bool anyDifferent = false;
    for (std::uint32_t seed : {2u, 3u, 17u, 12345u}) {
        const SkinnedModel other = GetParam().make(seed);
        ASSERT_EQ(other.vertices.size(), m.vertices.size()) << "seeds change proportions, not topology";
        EXPECT_EQ(other.indices, m.indices);
        const glm::vec3 size = m.boundsMax - m.boundsMin, otherSize = other.boundsMax - other.boundsMin;
        for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(otherSize[axis] / size[axis], 1.0f, 0.051f);
        anyDifferent = anyDifferent || otherSize != size;
        EXPECT_NEAR(other.boundsMin.y, 0.0f, 0.01f);
    }
    EXPECT_TRUE(anyDifferent);
}

INSTANTIATE_TEST_SUITE_P(BuiltIn, ProceduralModel, testing::Values(kSoldier, kHorse, kCavalry),
                         [](const testing::TestParamInfo<Character>& info) { return info.param.name; });

// ---- The soldier -------------------------------------------------------------------------------

class Soldier : public testing::Test {
protected:
    const SkinnedModel m = model::makeSoldier();
};

TEST_F(Soldier, IsAboutOnePointEightMetresTall) {
    EXPECT_GT(m.height(), 1.7f);
    EXPECT_LT(m.height(), 1.9f);
}

TEST_F(Soldier, FacesPlusZ) {
    // The toes are in front of the ankles.
    const glm::vec3 ankle = jointPosition(modelMatrices(m, m.skeleton.restPose), jointNamed(m, "foot_l"));
    const glm::vec3 toe = jointPosition(modelMatrices(m, m.skeleton.restPose), jointNamed(m, "toe_l"));
    EXPECT_GT(toe.z, ankle.z + 0.05f);
}

TEST_F(Soldier, ClipDurationsSuitTheirGaits) {
    EXPECT_NEAR(m.clips[m.findClip("idle")].duration, 3.0f, 0.5f);
    EXPECT_GE(m.clips[m.findClip("walk")].duration, 1.0f);
    EXPECT_LE(m.clips[m.findClip("walk")].duration, 1.2f);
    EXPECT_NEAR(m.clips[m.findClip("run")].duration, 0.7f, 0.1f);
}

TEST_F(Soldier, FeetStayOnTheGroundWhileWalkingAndStanding) {
    for (const char* clip : {"walk", "idle"}) {
        const float duration = m.clips[m.findClip(clip)].duration;
        for (int s = 0; s < 64; ++s) {
            const auto skinned = skinnedAt(m, clip, duration * (static_cast<float>(s) + 0.37f) / 64.0f);
            float lowest = std::numeric_limits<float>::max();
            for (const glm::vec3& p : skinned) lowest = std::min(lowest, p.y);
            EXPECT_GE(lowest, -0.05f) << clip << " sample " << s;
            EXPECT_LE(lowest, 0.15f) << clip << " sample " << s;
        }
    }
}

// In a walk and a run each arm swings forward with the opposite leg.
TEST_F(Soldier, ArmsSwingAgainstTheLegs) {
    const std::uint32_t handL = jointNamed(m, "hand_l"), handR = jointNamed(m, "hand_r");
    const std::uint32_t footL = jointNamed(m, "foot_l"), footR = jointNamed(m, "foot_r");
    for (const char* clip : {"walk", "run"}) {
        const float duration = m.clips[m.findClip(clip)].duration;
        float correlation = 0.0f, legTravel = 0.0f;
        for (int s = 0; s < 32; ++s) {
            const auto global = modelMatrices(m, sampledPose(m, clip, duration * static_cast<float>(s) / 32.0f));
            const float legs = jointPosition(global, footL).z - jointPosition(global, footR).z;
            const float arms = jointPosition(global, handL).z - jointPosition(global, handR).z;
            correlation += legs * arms;
            legTravel = std::max(legTravel, std::fabs(legs));
        }
        EXPECT_LT(correlation, 0.0f) << clip;
        EXPECT_GT(legTravel, 0.3f) << clip << ": the feet should pass each other by a stride";
    }
}

TEST_F(Soldier, HipsBobWhileWalking) {
    const std::uint32_t hips = jointNamed(m, "hips");
    const float duration = m.clips[m.findClip("walk")].duration;
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (int s = 0; s < 24; ++s) {
        const float y = sampledPose(m, "walk", duration * static_cast<float>(s) / 24.0f)[hips].translation.y;
        low = std::min(low, y);
        high = std::max(high, y);
    }
    EXPECT_GT(high - low, 0.01f);
    EXPECT_LT(high - low, 0.08f);
}

// ---- The horse ---------------------------------------------------------------------------------

class Horse : public testing::Test {
protected:
    const SkinnedModel m = model::makeHorse();

    // Each hoof (LH, LF, RH, RF) as the lowest point and the furthest-forward point of the
    // vertices its pastern carries, at a time in a clip.
    struct Hooves {
        std::array<float, 4> lowest, front;
    };
    Hooves hoovesAt(const std::string& clip, float time) const {
        const std::array<std::uint32_t, 4> pasterns = {
            jointNamed(m, "hind_pastern_l"), jointNamed(m, "front_pastern_l"),
            jointNamed(m, "hind_pastern_r"), jointNamed(m, "front_pastern_r")};
        const auto skinned = skinnedAt(m, clip, time);
        Hooves hooves;
        hooves.lowest.fill(std::numeric_limits<float>::max());
        hooves.front.fill(std::numeric_limits<float>::lowest());
        for (std::size_t i = 0; i < m.vertices.size(); ++i) {
            for (int leg = 0; leg < 4; ++leg) {
                if (dominantJoint(m.vertices[i]) != pasterns[leg]) continue;
                hooves.lowest[leg] = std::min(hooves.lowest[leg], skinned[i].y);
                hooves.front[leg] = std::max(hooves.front[leg], skinned[i].z);
            }
        }
        return hooves;
    }

    // For each hoof, the fraction of the loop at which it reaches furthest forward (about when it
    // strikes the ground). Checks on the way that every hoof is lifted clear at some point.
    std::array<float, 4> reachPhases(const std::string& clip) const {
        constexpr int kSamples = 96;
        const float duration = m.clips[m.findClip(clip)].duration;
        std::array<float, 4> furthest, phase{}, highest{};
        furthest.fill(std::numeric_limits<float>::lowest());
        for (int s = 0; s < kSamples; ++s) {
            const Hooves h = hoovesAt(clip, duration * static_cast<float>(s) / kSamples);
            for (int leg = 0; leg < 4; ++leg) {
                highest[leg] = std::max(highest[leg], h.lowest[leg]);
                if (h.front[leg] <= furthest[leg]) continue;
                furthest[leg] = h.front[leg];
                phase[leg] = static_cast<float>(s) / kSamples;
            }
        }
        for (int leg = 0; leg < 4; ++leg) EXPECT_GT(highest[leg], 0.1f) << clip << ": hoof " << leg << " barely lifts";
        return phase;
    }
};

// Distance between two phases round the loop, and a phase wrapped into [0, 1).
float phaseGap(float a, float b) {
    const float d = std::fabs(a - b);
    return std::min(d, 1.0f - d);
}
float wrapPhase(float phase) { return phase - std::floor(phase); }

TEST_F(Horse, IsAboutOnePointSixMetresAtTheWithersAndTwoPointFourLong) {
    // The withers are the top of the back over the front legs, where the neck rises.
    const float withersZ = jointPosition(modelMatrices(m, m.skeleton.restPose), jointNamed(m, "withers")).z;
    float top = 0.0f;
    for (const gpu::SkinVertex& v : m.vertices)
        if (std::fabs(v.position.z - withersZ) < 0.05f) top = std::max(top, v.position.y);
    EXPECT_NEAR(top, 1.6f, 0.08f);
    EXPECT_NEAR(m.boundsMax.z - m.boundsMin.z, 2.4f, 0.15f);
    EXPECT_GT(m.height(), top) << "the head is carried above the withers";
}

TEST_F(Horse, HasFourLegsOfAtLeastThreeSegments) {
    for (const char* leg : {"front_pastern_l", "front_pastern_r", "hind_pastern_l", "hind_pastern_r"}) {
        int depth = 0;
        for (std::int32_t j = static_cast<std::int32_t>(jointNamed(m, leg)); j >= 0; j = m.skeleton.parents[j]) ++depth;
        EXPECT_GE(depth, 5) << leg << ": pastern, cannon, forearm or gaskin, upper leg, then the body";
    }
}

TEST_F(Horse, ClipDurationsSuitTheirGaits) {
    EXPECT_NEAR(m.clips[m.findClip("walk")].duration, 1.1f, 0.1f);
    EXPECT_NEAR(m.clips[m.findClip("gallop")].duration, 0.6f, 0.1f);
}

TEST_F(Horse, WalkIsAFourBeatGait) {
    const std::array<float, 4> reach = reachPhases("walk");
    // Left hind, left fore, right hind, right fore: four evenly spaced beats.
    for (int leg = 0; leg < 4; ++leg)
        EXPECT_NEAR(wrapPhase(reach[(leg + 1) % 4] - reach[leg]), 0.25f, 0.05f) << "beat " << leg;
    const float duration = m.clips[m.findClip("walk")].duration;
    for (int s = 0; s < 32; ++s) {
        const auto h = hoovesAt("walk", duration * static_cast<float>(s) / 32.0f).lowest;
        // A hoof within 5 cm of the ground is taken to bear weight; a walk always has two or three down.
        EXPECT_GE(std::count_if(h.begin(), h.end(), [](float y) { return y < 0.05f; }), 2) << "sample " << s;
        EXPECT_GE(*std::min_element(h.begin(), h.end()), -0.02f);
    }
}

TEST_F(Horse, GallopMovesTheLegsInPairsAndRocksTheBody) {
    const std::array<float, 4> reach = reachPhases("gallop");
    EXPECT_LT(phaseGap(reach[0], reach[2]), 0.15f) << "hind pair";
    EXPECT_LT(phaseGap(reach[1], reach[3]), 0.15f) << "fore pair";
    EXPECT_GT(phaseGap(reach[0], reach[1]), 0.2f) << "the fore pair reaches well after the hinds";

    const std::uint32_t pelvis = jointNamed(m, "pelvis"), withers = jointNamed(m, "withers");
    const float duration = m.clips[m.findClip("gallop")].duration;
    float low = 90.0f, high = -90.0f;
    for (int s = 0; s < 24; ++s) {
        const auto global = modelMatrices(m, sampledPose(m, "gallop", duration * static_cast<float>(s) / 24.0f));
        const glm::vec3 back = jointPosition(global, withers) - jointPosition(global, pelvis);
        const float pitch = glm::degrees(std::atan2(back.y, back.z));
        low = std::min(low, pitch);
        high = std::max(high, pitch);
    }
    EXPECT_GT(high - low, 6.0f) << "the body pitches through the stride";
}

TEST_F(Horse, TailAndNeckSwing) {
    for (const char* clip : {"walk", "gallop"}) {
        const anim::Clip& c = m.clips[m.findClip(clip)];
        for (const char* joint : {"tail_1", "neck"}) {
            const std::uint32_t j = jointNamed(m, joint);
            EXPECT_TRUE(std::any_of(c.channels.begin(), c.channels.end(), [j](const anim::Channel& ch) {
                return ch.joint == j && ch.path == anim::ChannelPath::Rotation;
            })) << clip << " " << joint;
        }
    }
}

}  // namespace
