#include "render/shadow_cascades.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace render {
namespace {

// How far, in texels of its square, the shading's filter reads around a point (four bilinear
// comparisons half a texel away reach one texel) plus one: a cascade's own points keep it inside.
constexpr float kFilterReachTexels = 2.0f;

// Half logarithmic, half even: the logarithmic split alone gives the nearest cascade a sliver, the even
// one wastes the near texels (Zhang et al., "Parallel-split shadow maps", 2006).
constexpr float kLogarithmicShare = 0.5f;

struct Box {
    glm::vec3 lo{1e30f}, hi{-1e30f};
};

// The light-view box of the camera's view from distance `from` to `to`, above the ground (the plane at
// the ground's lowest, `ground`: a terrain's hills are above it): of the slice's eight corners those above
// it, and where its twelve edges cross it (a convex solid cut by a plane is the hull of those points;
// corners merely raised onto the ground would leave some of the ground out).
Box sliceBox(const Camera& camera, float aspect, const glm::mat4& lightView, float from, float to, float ground) {
    glm::mat4 projection = glm::perspective(camera.verticalFov, aspect, from, to);
    projection[1][1] *= -1.0f;
    const glm::mat4 inverse = glm::inverse(projection * glm::lookAt(camera.eye, camera.target, glm::vec3(0, 1, 0)));
    std::array<glm::vec3, 8> corners;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 clip((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : 0.0f, 1.0f);
        const glm::vec4 world = inverse * clip;
        corners[corner] = glm::vec3(world) / world.w;
    }
    Box box;
    auto hold = [&](const glm::vec3& world) {
        const glm::vec3 p = glm::vec3(lightView * glm::vec4(world, 1.0f));
        box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
    };
    for (int a = 0; a < 8; ++a) {
        if (corners[a].y >= ground) hold(corners[a]);
        for (int bit = 1; bit < 8; bit <<= 1) {  // each edge once: from the corner without the bit
            const int b = a | bit;
            if (b == a) continue;
            const float ya = corners[a].y - ground, yb = corners[b].y - ground;
            if ((ya < 0.0f) != (yb < 0.0f)) hold(glm::mix(corners[a], corners[b], ya / (ya - yb)));
        }
    }
    if (box.lo.x > box.hi.x) {  // the whole slice under the ground: nothing to shadow, any small box
        for (glm::vec3 corner : corners) hold(glm::vec3(corner.x, ground, corner.z));
    }
    return box;
}

std::array<float, kMostShadowCascades + 1> splitDistances(const Camera& camera, const CrowdShape& crowd,
                                                          float distance, std::uint32_t count) {
    std::array<float, kMostShadowCascades + 1> splits{};
    // Nothing nearer than the crowd's edge casts onto what the camera sees of it (from inside: the near plane).
    const float nearest = count == 1 ? camera.nearPlane
                                     : std::clamp(glm::distance(camera.eye, crowd.center) - crowd.radius,
                                                  camera.nearPlane, 0.5f * distance);
    for (std::uint32_t c = 0; c <= count; ++c) {
        const float t = static_cast<float>(c) / static_cast<float>(count);
        const float logarithmic = nearest * std::pow(distance / nearest, t);
        const float even = nearest + (distance - nearest) * t;
        splits[c] = kLogarithmicShare * logarithmic + (1.0f - kLogarithmicShare) * even;
    }
    splits[0] = nearest, splits[count] = distance;  // exact ends, whatever the rounding
    return splits;
}

}  // namespace

glm::mat4 ShadowCascades::mapClip(std::uint32_t c) const {
    // uv in the map = corner + (clip * 0.5 + 0.5) * side, so the map's clip = clip * side + 2 corner + side - 1.
    const glm::vec4 s = square[c];
    const glm::vec3 offset(2.0f * s.x + s.z - 1.0f, 2.0f * s.y + s.z - 1.0f, 0.0f);
    return glm::translate(glm::mat4(1.0f), offset) * glm::scale(glm::mat4(1.0f), glm::vec3(s.z, s.z, 1.0f)) * clip[c];
}

VkRect2D ShadowCascades::texels(std::uint32_t c, std::uint32_t mapSize) const {
    const float size = static_cast<float>(mapSize);
    const auto side = static_cast<std::uint32_t>(square[c].z * size);
    return {{static_cast<std::int32_t>(square[c].x * size), static_cast<std::int32_t>(square[c].y * size)}, {side, side}};
}

ShadowCascades shadowCascades(const Camera& camera, float aspect, const CrowdShape& crowd, const glm::vec3& towardsLight,
                              std::uint32_t count, std::uint32_t mapSize) {
    ShadowCascades cascades;
    cascades.count = std::clamp(count, 1u, kMostShadowCascades);
    const float reach = glm::distance(camera.eye, crowd.center) + crowd.radius;
    const float distance = std::clamp(reach, camera.nearPlane * 2.0f, 60.0f * crowd.characterHeight);
    cascades.splits = splitDistances(camera, crowd, distance, cascades.count);

    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    cascades.view = glm::vec4(forward, -glm::dot(forward, camera.eye));
    const glm::vec3 centre = 0.5f * (camera.eye + camera.target);
    const glm::mat4 lightView = glm::lookAt(centre + towardsLight, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    std::array<Box, kMostShadowCascades> boxes{};
    Box all;
    for (std::uint32_t c = 0; c < cascades.count; ++c) {
        boxes[c] = sliceBox(camera, aspect, lightView, cascades.splits[c], cascades.splits[c + 1], crowd.ground);
        all.lo = glm::min(all.lo, boxes[c].lo), all.hi = glm::max(all.hi, boxes[c].hi);
    }
    // One depth range for all: casters stand up to a few character heights above the region, towards the
    // light (+z in view space).
    const float zFar = all.lo.z - crowd.characterHeight;
    const float zNear = all.hi.z + 4.0f * crowd.characterHeight + crowd.radius * 0.05f;

    // Several cascades share the map in quarters, each widened so its stretch keeps the filter inside.
    const float side = cascades.count == 1 ? 1.0f : 0.5f;
    const float squareTexels = side * static_cast<float>(mapSize);
    const float reachTexels = cascades.count == 1 ? 0.0f : kFilterReachTexels;
    cascades.ownedWithin = 1.0f - 2.0f * reachTexels / squareTexels;
    // Widened half a texel more than the reach, so the stretch's own edge is inside `ownedWithin` by more
    // than rounding.
    const float widenTexels = cascades.count == 1 ? 0.0f : reachTexels + 0.5f;
    for (std::uint32_t c = 0; c < cascades.count; ++c) {
        Box b = boxes[c];
        const glm::vec3 widen = (b.hi - b.lo) * (widenTexels / (squareTexels - 2.0f * widenTexels));
        b.lo -= widen, b.hi += widen;
        cascades.clip[c] = glm::ortho(b.lo.x, b.hi.x, b.lo.y, b.hi.y, -zNear, -zFar) * lightView;
        boxes[c] = b;
        // clip_c = 2 (x - lo_c) / w_c - 1 and x = (clip_0 + 1) w_0 / 2 + lo_0, per axis.
        const glm::vec2 w0 = glm::vec2(boxes[0].hi - boxes[0].lo), wc = glm::vec2(b.hi - b.lo);
        cascades.fromFirst[c] = glm::vec4(w0 / wc, (w0 + 2.0f * (glm::vec2(boxes[0].lo) - glm::vec2(b.lo))) / wc - 1.0f);
        cascades.square[c] = glm::vec4(cascades.count == 1 ? 0.0f : 0.5f * static_cast<float>(c & 1u),
                                       cascades.count == 1 ? 0.0f : 0.5f * static_cast<float>(c >> 1), side, 0.0f);
    }
    return cascades;
}

std::uint32_t ShadowCascades::stretchOf(const glm::vec3& world) const {
    const float along = glm::dot(glm::vec3(view), world) + view.w;
    std::uint32_t stretch = 0;
    while (stretch + 1 < count && along > splits[stretch + 1]) ++stretch;
    return stretch;
}

int cascadeHolding(const ShadowCascades& cascades, const glm::vec3& world) {
    const std::uint32_t stretch = cascades.stretchOf(world);
    for (std::uint32_t c = stretch; c < std::min(stretch + 2, cascades.count); ++c) {
        const glm::vec4 p = cascades.clip[c] * glm::vec4(world, 1.0f);
        if (std::abs(p.x) <= cascades.ownedWithin && std::abs(p.y) <= cascades.ownedWithin && p.z <= 1.0f)
            return static_cast<int>(c);
    }
    return -1;
}

}  // namespace render
