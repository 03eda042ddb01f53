// The built-in soldier: a low-poly humanoid in helmet and uniform, a rifle in its right hand (a prop),
// and for some a flag in the left.
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "model/attach_prop.h"
#include "model/footsteps.h"
#include "model/mesh_builder.h"
#include "model/procedural_models.h"
#include "model/seeded_variation.h"
#include "model/skeleton_builder.h"
#include "model/soldier_clips.h"

namespace model {
namespace {

enum Material : std::uint32_t { Skin, Uniform, Boots, Helmet, Metal, Wood, Webbing };

std::vector<glm::vec4> soldierPalette() {
    // Linear RGB: olive drab, dark leather and a darker green helmet read as a soldier at a distance.
    return {
        {0.62f, 0.38f, 0.26f, 1.0f},    // Skin
        {0.15f, 0.17f, 0.07f, 1.0f},    // Uniform
        {0.03f, 0.025f, 0.02f, 1.0f},   // Boots
        {0.08f, 0.10f, 0.05f, 1.0f},    // Helmet
        {0.025f, 0.025f, 0.03f, 1.0f},  // Metal
        {0.18f, 0.08f, 0.03f, 1.0f},    // Wood
        {0.10f, 0.09f, 0.05f, 1.0f},    // Webbing
    };
}

// The parts below are placed for a man 1.84 m tall to the top of the helmet; this brings the
// average soldier to 1.80 m.
constexpr float kModelledToAverage = 1.80f / 1.84f;

// Blend bands round the joints: wide enough to take in the rings either side of a knee or elbow;
// the spine bends over a longer stretch.
constexpr float kJointBand = 0.06f;
constexpr float kTorsoBand = 0.10f;

struct Joints {
    std::uint32_t hips, spine, chest, neck, head;
    std::uint32_t clavicle[2], upperArm[2], forearm[2], hand[2];
    std::uint32_t thigh[2], shin[2], foot[2], toe[2];
};

// Side 0 is the soldier's left (+x, since it faces +z), side 1 its right.
float sideSign(int side) { return side == 0 ? 1.0f : -1.0f; }
const char* sideSuffix(int side) { return side == 0 ? "_l" : "_r"; }

Joints addJoints(SkeletonBuilder& b) {
    Joints j;
    j.hips = b.add("hips", -1, {0.0f, 0.98f, 0.0f});
    j.spine = b.add("spine", j.hips, {0.0f, 1.12f, 0.0f});
    j.chest = b.add("chest", j.spine, {0.0f, 1.30f, 0.0f});
    j.neck = b.add("neck", j.chest, {0.0f, 1.50f, 0.0f});
    j.head = b.add("head", j.neck, {0.0f, 1.60f, 0.01f});
    for (int side = 0; side < 2; ++side) {
        const float s = sideSign(side);
        const std::string suffix = sideSuffix(side);
        j.clavicle[side] = b.add("clavicle" + suffix, j.chest, {s * 0.04f, 1.45f, 0.0f});
        j.upperArm[side] = b.add("upperarm" + suffix, j.clavicle[side], {s * 0.20f, 1.45f, 0.0f});
        j.forearm[side] = b.add("forearm" + suffix, j.upperArm[side], {s * 0.235f, 1.17f, 0.0f});
        j.hand[side] = b.add("hand" + suffix, j.forearm[side], {s * 0.258f, 0.93f, 0.01f});
    }
    for (int side = 0; side < 2; ++side) {
        const float s = sideSign(side);
        const std::string suffix = sideSuffix(side);
        j.thigh[side] = b.add("thigh" + suffix, j.hips, {s * 0.10f, 0.93f, 0.0f});
        j.shin[side] = b.add("shin" + suffix, j.thigh[side], {s * 0.10f, 0.51f, 0.01f});
        j.foot[side] = b.add("foot" + suffix, j.shin[side], {s * 0.10f, 0.09f, -0.01f});
        j.toe[side] = b.add("toe" + suffix, j.foot[side], {s * 0.10f, 0.03f, 0.13f});
    }
    return j;
}

std::function<Influences(const glm::vec3&)> skinAlong(const SkeletonBuilder& b, std::vector<std::uint32_t> joints,
                                                      float band = kJointBand) {
    std::vector<glm::vec3> positions = b.positions(joints);
    return chainSkin(std::move(joints), std::move(positions), band);
}

// Rings along y for an upright part; r is (half width in x, half depth in z).
Ring upright(float y, glm::vec2 r, std::uint32_t material, float z = 0.0f, float x = 0.0f) {
    return {{x, y, z}, r, material};
}

void addTorso(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    Tube torso;
    torso.segments = 10;
    torso.rings = {
        upright(0.83f, {0.0f, 0.0f}, Uniform),
        upright(0.87f, {0.13f, 0.09f}, Uniform),
        upright(0.94f, {0.165f, 0.105f}, Uniform, -0.01f),
        upright(1.01f, {0.17f, 0.11f}, Webbing),  // belt
        upright(1.05f, {0.165f, 0.108f}, Uniform),
        upright(1.14f, {0.155f, 0.10f}, Uniform),
        upright(1.28f, {0.175f, 0.113f}, Uniform, 0.008f),
        upright(1.35f, {0.185f, 0.12f}, Uniform, 0.015f),
        upright(1.43f, {0.19f, 0.11f}, Uniform, 0.005f),
        upright(1.475f, {0.16f, 0.09f}, Uniform),
        upright(1.505f, {0.08f, 0.06f}, Uniform),
        upright(1.515f, {0.0f, 0.0f}, Uniform),
    };
    torso.skin = skinAlong(b, {j.hips, j.spine, j.chest, j.neck}, kTorsoBand);
    addTube(m, torso);

    Tube neck;
    neck.rings = {upright(1.46f, {0.055f, 0.055f}, Skin), upright(1.56f, {0.05f, 0.05f}, Skin, 0.005f),
                  upright(1.63f, {0.05f, 0.05f}, Skin, 0.01f)};
    neck.skin = skinAlong(b, {j.chest, j.neck, j.head});
    addTube(m, neck);
}

// An ellipsoid of tube rings between two poles, at evenly spaced latitudes.
std::vector<Ring> ellipsoid(glm::vec3 center, glm::vec3 radius, int rings, std::uint32_t material) {
    std::vector<Ring> result;
    for (int i = 0; i <= rings + 1; ++i) {
        const float latitude = std::numbers::pi_v<float> * (static_cast<float>(i) / static_cast<float>(rings + 1) - 0.5f);
        const float across = (i == 0 || i == rings + 1) ? 0.0f : std::cos(latitude);
        result.push_back(upright(center.y + radius.y * std::sin(latitude), {radius.x * across, radius.z * across},
                                 material, center.z, center.x));
    }
    return result;
}

void addHead(SkinnedModel& m, const Joints& j) {
    Tube head;
    head.segments = 8;
    head.rings = ellipsoid({0.0f, 1.70f, 0.015f}, {0.085f, 0.11f, 0.10f}, 5, Skin);
    head.skin = rigidSkin(j.head);
    addTube(m, head);

    Box nose;
    nose.center = {0.0f, 1.69f, 0.115f};
    nose.halfExtent = {0.015f, 0.022f, 0.015f};
    nose.material = Skin;
    nose.skin = rigid(j.head);
    addBox(m, nose);

    // A steel pot, widest at the brim, sitting low over the brow.
    Tube helmet;
    helmet.segments = 10;
    helmet.rings = {
        upright(1.70f, {0.134f, 0.144f}, Helmet, 0.005f), upright(1.725f, {0.123f, 0.133f}, Helmet),
        upright(1.775f, {0.108f, 0.118f}, Helmet),        upright(1.815f, {0.075f, 0.082f}, Helmet),
        upright(1.84f, {0.0f, 0.0f}, Helmet),
    };
    helmet.skin = rigidSkin(j.head);
    addTube(m, helmet);
}

void addArm(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j, int side) {
    const float s = sideSign(side);
    auto at = [s](float x, float y, float z, glm::vec2 r, std::uint32_t material) {
        return Ring{{s * x, y, z}, r, material};
    };
    Tube arm;
    // Sleeve to a cuff just above the wrist, then a flat hand (thin in x, wide in z) closing at the fingertips.
    arm.rings = {
        at(0.195f, 1.48f, 0.0f, {0.0f, 0.0f}, Uniform),         at(0.20f, 1.45f, 0.0f, {0.055f, 0.06f}, Uniform),
        at(0.205f, 1.38f, 0.0f, {0.056f, 0.06f}, Uniform),      at(0.235f, 1.17f, 0.0f, {0.044f, 0.047f}, Uniform),
        at(0.245f, 1.08f, 0.0f, {0.045f, 0.048f}, Uniform),     at(0.255f, 0.95f, 0.01f, {0.042f, 0.045f}, Skin),
        at(0.258f, 0.935f, 0.01f, {0.03f, 0.034f}, Skin),       at(0.263f, 0.87f, 0.012f, {0.024f, 0.045f}, Skin),
        at(0.268f, 0.79f, 0.015f, {0.02f, 0.038f}, Skin),       at(0.272f, 0.745f, 0.018f, {0.0f, 0.0f}, Skin),
    };
    arm.skin = skinAlong(b, {j.clavicle[side], j.upperArm[side], j.forearm[side], j.hand[side]});
    addTube(m, arm);
}

void addLeg(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j, int side) {
    const float s = sideSign(side);
    auto at = [s](float y, float z, glm::vec2 r, std::uint32_t material) {
        return Ring{{s * 0.10f, y, z}, r, material};
    };
    Tube leg;
    // Trousers bloused into boots at mid-calf; the tube starts inside the hips so a swinging thigh
    // never opens a gap at the crotch.
    leg.rings = {
        at(1.02f, 0.0f, {0.0f, 0.0f}, Uniform),        at(0.96f, 0.0f, {0.085f, 0.09f}, Uniform),
        at(0.82f, 0.005f, {0.078f, 0.083f}, Uniform),  at(0.52f, 0.01f, {0.056f, 0.06f}, Uniform),
        at(0.40f, 0.0f, {0.062f, 0.068f}, Uniform),    at(0.30f, -0.005f, {0.06f, 0.065f}, Boots),
        at(0.12f, -0.008f, {0.05f, 0.056f}, Boots),    at(0.07f, -0.01f, {0.048f, 0.054f}, Boots),
    };
    leg.skin = skinAlong(b, {j.hips, j.thigh[side], j.shin[side], j.foot[side]});
    addTube(m, leg);

    Tube foot;
    foot.segments = 6;
    foot.side = {1.0f, 0.0f, 0.0f};
    // Along +z from heel to toe: radius x is the half width, radius y the half height, sole at y = 0.
    foot.rings = {
        {{s * 0.10f, 0.055f, -0.075f}, {0.045f, 0.05f}, Boots},
        {{s * 0.10f, 0.06f, -0.02f}, {0.05f, 0.06f}, Boots},
        {{s * 0.10f, 0.05f, 0.07f}, {0.052f, 0.05f}, Boots},
        {{s * 0.10f, 0.04f, 0.15f}, {0.045f, 0.04f}, Boots},
        {{s * 0.10f, 0.035f, 0.19f}, {0.0f, 0.0f}, Boots},
    };
    foot.skin = skinAlong(b, {j.foot[side], j.toe[side]});
    addTube(m, foot);
}

// Ammunition pouches on the front of the belt.
void addPouches(SkinnedModel& m, const Joints& j) {
    for (float x : {-0.085f, 0.085f}) {
        Box pouch;
        pouch.center = {x, 1.02f, 0.105f};
        pouch.halfExtent = {0.045f, 0.04f, 0.025f};
        pouch.material = Webbing;
        pouch.skin = rigid(j.hips);
        addBox(m, pouch);
    }
}

// The props, attached once the clips are made (they plant the feet on the body alone). The hands'
// bind frames are the model's axes; a hand closes about 8 cm below its joint. The rifle is carried
// muzzle a little down, as the walk swings it; the idle clip raises the right forearm so that the
// same offset rests it on the shoulder (soldier_clips.cpp). One soldier in eight carries a flag.
constexpr float kFlagShare = 0.125f;

void addProps(SkinnedModel& soldier, glm::vec3 stretch) {
    const glm::vec3 grip = glm::vec3(0.008f, -0.085f, 0.01f) * stretch;
    const glm::mat4 rifle = glm::rotate(glm::translate(glm::mat4(1.0f), grip * glm::vec3(-1.0f, 1.0f, 1.0f)),
                                        glm::radians(10.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    attachProp(soldier, makeRifle(), "hand_r", rifle);
    attachProp(soldier, makeFlag(), "hand_l", glm::translate(glm::mat4(1.0f), grip), kFlagShare);
}

}  // namespace

SkinnedModel makeSoldier(std::uint32_t seed, bool props) {
    // Proportions vary a little per seed: height by up to 3 %, build (width and depth) by up to 5 %.
    const float height = seededScale(seed, 0, 0.03f);
    const float build = seededScale(seed, 1, 0.05f);
    const glm::vec3 stretch = kModelledToAverage * glm::vec3(build, height, build);

    SkinnedModel soldier;
    soldier.name = "soldier";
    soldier.materialColors = soldierPalette();
    SkeletonBuilder bones;
    const Joints joints = addJoints(bones);
    addTorso(soldier, bones, joints);
    addHead(soldier, joints);
    for (int side = 0; side < 2; ++side) {
        addArm(soldier, bones, joints, side);
        addLeg(soldier, bones, joints, side);
    }
    addPouches(soldier, joints);
    stretchVertices(soldier, stretch);
    soldier.skeleton = bones.build(stretch);
    soldier.clips = makeSoldierClips(soldier);
    if (props) addProps(soldier, stretch);
    computeBounds(soldier);
    // Last, on the finished mesh and clips: footsteps are found where the skinned feet touch down.
    attachFootsteps(soldier, {"foot_l", "foot_r"});
    return soldier;
}

}  // namespace model
