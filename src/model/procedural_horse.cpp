// The built-in horse: a bay (brown coat, black mane, tail and lower legs) about 1.6 m at the withers.
#include "model/horse_clips.h"
#include "model/footsteps.h"
#include "model/mesh_builder.h"
#include "model/procedural_models.h"
#include "model/seeded_variation.h"
#include "model/skeleton_builder.h"

namespace model {
namespace {

enum Material : std::uint32_t { Coat, Points, Hoof, Muzzle };

std::vector<glm::vec4> horsePalette() {
    return {
        {0.30f, 0.12f, 0.045f, 1.0f},   // Coat
        {0.025f, 0.02f, 0.018f, 1.0f},  // Points: mane, tail, lower legs, eyes
        {0.09f, 0.08f, 0.07f, 1.0f},    // Hoof
        {0.08f, 0.045f, 0.03f, 1.0f},   // Muzzle
    };
}

// The body's bones are long, so its blend bands are wide; legs bend over a shorter band.
constexpr float kBodyBand = 0.15f;
constexpr float kNeckAndTailBand = 0.12f;
constexpr float kLimbBand = 0.06f;

struct Joints {
    std::uint32_t pelvis, spine, withers, neck, neckUpper, head, tail[3];
    std::uint32_t upperArm[2], forearm[2], frontCannon[2], frontPastern[2];
    std::uint32_t thigh[2], gaskin[2], hindCannon[2], hindPastern[2];
};

// Side 0 is the horse's left (+x, since it faces +z), side 1 its right.
float sideSign(int side) { return side == 0 ? 1.0f : -1.0f; }
const char* sideSuffix(int side) { return side == 0 ? "_l" : "_r"; }
constexpr float kLegX = 0.17f;

Joints addJoints(SkeletonBuilder& b) {
    Joints j;
    j.pelvis = b.add("pelvis", -1, {0.0f, 1.30f, -0.55f});
    j.spine = b.add("spine", j.pelvis, {0.0f, 1.32f, -0.05f});
    j.withers = b.add("withers", j.spine, {0.0f, 1.38f, 0.38f});
    j.neck = b.add("neck", j.withers, {0.0f, 1.42f, 0.58f});
    j.neckUpper = b.add("neck_upper", j.neck, {0.0f, 1.63f, 0.775f});
    j.head = b.add("head", j.neckUpper, {0.0f, 1.86f, 0.93f});
    j.tail[0] = b.add("tail_1", j.pelvis, {0.0f, 1.42f, -0.86f});
    j.tail[1] = b.add("tail_2", j.tail[0], {0.0f, 1.22f, -0.94f});
    j.tail[2] = b.add("tail_3", j.tail[1], {0.0f, 0.98f, -0.98f});
    for (int side = 0; side < 2; ++side) {
        const float x = sideSign(side) * kLegX;
        const std::string suffix = sideSuffix(side);
        j.upperArm[side] = b.add("upperarm" + suffix, j.withers, {x, 1.22f, 0.45f});
        j.forearm[side] = b.add("forearm" + suffix, j.upperArm[side], {x, 0.92f, 0.37f});
        j.frontCannon[side] = b.add("front_cannon" + suffix, j.forearm[side], {x, 0.50f, 0.38f});
        j.frontPastern[side] = b.add("front_pastern" + suffix, j.frontCannon[side], {x, 0.16f, 0.38f});
    }
    for (int side = 0; side < 2; ++side) {
        const float x = sideSign(side) * kLegX;
        const std::string suffix = sideSuffix(side);
        j.thigh[side] = b.add("thigh" + suffix, j.pelvis, {x, 1.22f, -0.55f});
        j.gaskin[side] = b.add("gaskin" + suffix, j.thigh[side], {x, 0.92f, -0.42f});
        j.hindCannon[side] = b.add("hind_cannon" + suffix, j.gaskin[side], {x, 0.53f, -0.63f});
        j.hindPastern[side] = b.add("hind_pastern" + suffix, j.hindCannon[side], {x, 0.16f, -0.62f});
    }
    // Where a rider sits (Model::mounted): on the top line of the back behind the withers, moving with
    // the spine. No vertex follows it; added last so that the other joints keep their indices.
    b.add("saddle", j.spine, {0.0f, 1.545f, 0.02f});
    return j;
}

std::function<Influences(const glm::vec3&)> skinAlong(const SkeletonBuilder& b, std::vector<std::uint32_t> joints,
                                                      float band) {
    std::vector<glm::vec3> positions = b.positions(joints);
    return chainSkin(std::move(joints), std::move(positions), band);
}

// A ring at (x, y, z); for a tube along z radius is (half width, half height), for one along y
// (half width, half depth).
Ring ring(float x, float y, float z, glm::vec2 radius, std::uint32_t material) {
    return {{x, y, z}, radius, material};
}

void addBody(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    Tube body;
    body.segments = 14;
    // Rump to chest along +z: round quarters, a deep barrel, the withers highest over the front legs.
    body.rings = {
        ring(0, 1.30f, -0.93f, {0.0f, 0.0f}, Coat),    ring(0, 1.31f, -0.90f, {0.10f, 0.14f}, Coat),
        ring(0, 1.30f, -0.84f, {0.18f, 0.24f}, Coat),  ring(0, 1.28f, -0.72f, {0.22f, 0.29f}, Coat),
        ring(0, 1.26f, -0.52f, {0.24f, 0.31f}, Coat),  ring(0, 1.22f, -0.30f, {0.26f, 0.32f}, Coat),
        ring(0, 1.20f, -0.05f, {0.27f, 0.33f}, Coat),  ring(0, 1.23f, 0.18f, {0.26f, 0.34f}, Coat),
        ring(0, 1.27f, 0.36f, {0.23f, 0.33f}, Coat),   ring(0, 1.24f, 0.50f, {0.20f, 0.30f}, Coat),
        ring(0, 1.20f, 0.62f, {0.16f, 0.22f}, Coat),   ring(0, 1.19f, 0.68f, {0.10f, 0.12f}, Coat),
        ring(0, 1.19f, 0.70f, {0.0f, 0.0f}, Coat),
    };
    body.skin = skinAlong(b, {j.pelvis, j.spine, j.withers}, kBodyBand);
    addTube(m, body);
}

// The neck's centre line from inside the chest to the poll, with (half width, half depth).
struct NeckPoint {
    glm::vec3 center;
    glm::vec2 radius;
};
const NeckPoint kNeck[] = {
    {{0.0f, 1.30f, 0.48f}, {0.14f, 0.24f}}, {{0.0f, 1.45f, 0.63f}, {0.12f, 0.20f}},
    {{0.0f, 1.62f, 0.77f}, {0.10f, 0.15f}}, {{0.0f, 1.78f, 0.88f}, {0.085f, 0.12f}},
    {{0.0f, 1.88f, 0.95f}, {0.08f, 0.10f}},
};

void addNeckAndMane(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    Tube neck;
    neck.segments = 10;
    for (const NeckPoint& p : kNeck) neck.rings.push_back({p.center, p.radius, Coat});
    neck.skin = skinAlong(b, {j.withers, j.neck, j.neckUpper, j.head}, kNeckAndTailBand);
    addTube(m, neck);

    // The mane runs along the crest: the top-back edge of the neck, as a thin dark fin.
    Tube mane;
    mane.segments = 6;
    const glm::vec3 side = {1.0f, 0.0f, 0.0f};
    mane.rings.push_back({{0.0f, 1.50f, 0.40f}, {0.0f, 0.0f}, Points});
    for (std::size_t i = 1; i < std::size(kNeck); ++i) {
        const glm::vec3 along = glm::normalize(kNeck[i].center - kNeck[i - 1].center);
        const glm::vec3 crest = glm::cross(along, side);  // up and back, across the neck
        const float height = i + 1 == std::size(kNeck) ? 0.04f : 0.06f;
        mane.rings.push_back({kNeck[i].center + crest * (kNeck[i].radius.y + 0.01f), {0.025f, height}, Points});
    }
    mane.rings.push_back({kNeck[std::size(kNeck) - 1].center + glm::vec3(0.0f, 0.12f, 0.04f), {0.0f, 0.0f}, Points});
    mane.skin = skinAlong(b, {j.withers, j.neck, j.neckUpper, j.head}, kNeckAndTailBand);
    addTube(m, mane);
}

void addHead(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    // From behind the poll down to the muzzle: deep at the jowl, narrow at the nose, flared nostrils.
    const glm::vec3 poll = {0.0f, 1.95f, 0.92f}, nose = {0.0f, 1.46f, 1.33f};
    const glm::vec3 along = glm::normalize(nose - poll);
    const glm::vec3 down = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), along);  // towards the jaw
    auto at = [&](float s, float jaw, glm::vec2 radius, std::uint32_t material) {
        return Ring{glm::mix(poll, nose, s) + jaw * down, radius, material};
    };
    Tube head;
    head.segments = 10;
    head.rings = {
        at(0.0f, 0.0f, {0.0f, 0.0f}, Coat),          at(0.07f, 0.01f, {0.085f, 0.10f}, Coat),
        at(0.25f, 0.04f, {0.10f, 0.14f}, Coat),      at(0.50f, 0.01f, {0.08f, 0.10f}, Coat),
        at(0.76f, 0.0f, {0.065f, 0.085f}, Muzzle),   at(0.93f, 0.0f, {0.07f, 0.08f}, Muzzle),
        at(1.0f, 0.0f, {0.0f, 0.0f}, Muzzle),
    };
    head.skin = skinAlong(b, {j.neckUpper, j.head}, kLimbBand);
    addTube(m, head);

    for (int side = 0; side < 2; ++side) {
        const float s = sideSign(side);
        Tube ear;
        ear.segments = 4;
        ear.side = {0.0f, 0.0f, 1.0f};
        ear.rings = {{{s * 0.05f, 1.94f, 0.93f}, {0.03f, 0.018f}, Coat},
                     {{s * 0.058f, 2.01f, 0.925f}, {0.025f, 0.014f}, Coat},
                     {{s * 0.065f, 2.08f, 0.91f}, {0.0f, 0.0f}, Coat}};
        ear.skin = rigidSkin(j.head);
        addTube(m, ear);

        Box eye;
        eye.center = glm::mix(poll, nose, 0.2f) + glm::vec3(s * 0.085f, 0.0f, 0.0f);
        eye.halfExtent = {0.012f, 0.02f, 0.02f};
        eye.material = Points;
        eye.skin = rigid(j.head);
        addBox(m, eye);
    }
}

// A leg from inside the body to the hoof; rings are (height, z, half width, half depth, material)
// and the lower leg below the knee or hock is black, as on a bay.
struct LegRing {
    float y, z;
    glm::vec2 radius;
    std::uint32_t material;
};

void addLeg(SkinnedModel& m, const SkeletonBuilder& b, std::vector<std::uint32_t> chain, float x,
            std::initializer_list<LegRing> rings) {
    Tube leg;
    // Above the elbow or stifle the leg curves in under the body, so a swinging leg does not poke out.
    auto tuckedX = [x](float y) { return x * (1.0f - 0.35f * glm::smoothstep(0.95f, 1.2f, y)); };
    for (const LegRing& r : rings) leg.rings.push_back({{tuckedX(r.y), r.y, r.z}, r.radius, r.material});
    leg.skin = skinAlong(b, std::move(chain), kLimbBand);
    addTube(m, leg);
}

void addLegs(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    for (int side = 0; side < 2; ++side) {
        const float x = sideSign(side) * kLegX;
        addLeg(m, b, {j.withers, j.upperArm[side], j.forearm[side], j.frontCannon[side], j.frontPastern[side]}, x,
               {{1.25f, 0.44f, {0.0f, 0.0f}, Coat},       {1.12f, 0.42f, {0.10f, 0.13f}, Coat},
                {0.92f, 0.37f, {0.075f, 0.10f}, Coat},    {0.75f, 0.375f, {0.06f, 0.075f}, Coat},
                {0.51f, 0.38f, {0.05f, 0.06f}, Points},   {0.40f, 0.38f, {0.038f, 0.045f}, Points},
                {0.17f, 0.38f, {0.045f, 0.055f}, Points}, {0.10f, 0.395f, {0.037f, 0.042f}, Points},
                {0.075f, 0.415f, {0.045f, 0.05f}, Hoof},  {0.0f, 0.415f, {0.056f, 0.062f}, Hoof}});
        addLeg(m, b, {j.pelvis, j.thigh[side], j.gaskin[side], j.hindCannon[side], j.hindPastern[side]}, x,
               {{1.32f, -0.56f, {0.0f, 0.0f}, Coat},       {1.18f, -0.53f, {0.12f, 0.20f}, Coat},
                {0.92f, -0.43f, {0.09f, 0.14f}, Coat},     {0.72f, -0.52f, {0.06f, 0.09f}, Coat},
                {0.535f, -0.625f, {0.045f, 0.07f}, Points}, {0.40f, -0.625f, {0.038f, 0.048f}, Points},
                {0.17f, -0.62f, {0.045f, 0.055f}, Points}, {0.10f, -0.605f, {0.037f, 0.042f}, Points},
                {0.075f, -0.585f, {0.045f, 0.05f}, Hoof},  {0.0f, -0.585f, {0.056f, 0.062f}, Hoof}});
    }
}

void addTail(SkinnedModel& m, const SkeletonBuilder& b, const Joints& j) {
    Tube tail;
    // The dock leaves the rump, then the hair falls and spreads before thinning to the tip.
    tail.rings = {
        ring(0, 1.45f, -0.84f, {0.045f, 0.05f}, Points),  ring(0, 1.33f, -0.915f, {0.055f, 0.065f}, Points),
        ring(0, 1.21f, -0.95f, {0.07f, 0.08f}, Points),   ring(0, 0.99f, -0.98f, {0.08f, 0.09f}, Points),
        ring(0, 0.80f, -0.99f, {0.07f, 0.08f}, Points),   ring(0, 0.62f, -0.98f, {0.0f, 0.0f}, Points),
    };
    tail.skin = skinAlong(b, {j.pelvis, j.tail[0], j.tail[1], j.tail[2]}, kNeckAndTailBand);
    addTube(m, tail);
}

}  // namespace

SkinnedModel makeHorse(std::uint32_t seed) {
    // Proportions vary a little per seed: height 3 %, length 4 %, girth 5 % at most.
    const glm::vec3 stretch = {seededScale(seed, 2, 0.05f), seededScale(seed, 3, 0.03f), seededScale(seed, 4, 0.04f)};
    SkinnedModel horse;
    horse.name = "horse";
    horse.materialColors = horsePalette();
    SkeletonBuilder bones;
    const Joints joints = addJoints(bones);
    addBody(horse, bones, joints);
    addNeckAndMane(horse, bones, joints);
    addHead(horse, bones, joints);
    addLegs(horse, bones, joints);
    addTail(horse, bones, joints);
    stretchVertices(horse, stretch);
    horse.skeleton = bones.build(stretch);
    horse.clips = makeHorseClips(horse);
    computeBounds(horse);
    // Last, on the finished mesh and clips: footsteps are found where the skinned feet touch down.
    attachFootsteps(horse, {"front_pastern_l", "front_pastern_r", "hind_pastern_l", "hind_pastern_r"});
    return horse;
}

}  // namespace model
