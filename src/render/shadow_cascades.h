#pragma once
// The sun's shadow cascades (issue 18, "shadows that cost what they show"). One map over the whole view
// spends as many texels on the far field, where a character is a few pixels tall, as next to the camera,
// where its shadow is large. Cascades split the view by distance: cascade c holds the view from
// splits[c] to splits[c + 1] in its own square of the one shadow map (with 2 to 4 cascades, a quarter of
// it each), so the near stretch gets many texels per metre and the far one few. The map, its depth
// buffer, copy and ground sunlight image stay one image each: the cost per frame is the same texels.
//
// Every cascade looks along the same light view and shares its depth range, so depths (and the depth
// bias) mean the same in all; only their x, y extents differ. Each is widened by the shading filter's
// reach, so a point of its stretch is its own with the filter inside its square (`ownedWithin`); the
// shading takes the cascade of the point's stretch, or the next if that one does not own it
// (shading.glsl.inc, shadowLookup; cascadeHolding here is its mirror for tests).
#include <array>
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "gpu_types.h"
#include "render/camera.h"

namespace render {

inline constexpr std::uint32_t kMostShadowCascades = MAX_SHADOW_CASCADES;
inline constexpr std::uint32_t kDefaultShadowCascades = 1;
// Several cascades share the map in quarters, each widened by the filter's reach: below this a quarter
// would be mostly margin.
inline constexpr std::uint32_t kLeastCascadedMapSize = 64;

struct ShadowCascades {
    std::uint32_t count = 1;
    std::array<glm::mat4, kMostShadowCascades> clip{};    // world to the cascade's clip space (its square: x, y in [-1, 1])
    std::array<glm::vec4, kMostShadowCascades> square{};  // its square in the map: xy corner, z side (uv)
    // Its clip x, y from the first cascade's: clip = first * xy + zw (the same light view, other extents).
    std::array<glm::vec4, kMostShadowCascades> fromFirst{};
    std::array<float, kMostShadowCascades + 1> splits{};  // view distances: c holds splits[c] to splits[c + 1]
    float ownedWithin = 1.0f;  // |clip x, y| within which a point is the cascade's own (SceneUniforms)
    glm::vec4 view{0.0f};      // a point's distance along the view (as the splits): dot(xyz, point) + w

    // The stretch of the view a point lies in, by its distance along the view.
    std::uint32_t stretchOf(const glm::vec3& world) const;

    // World to the whole map's clip space, landing in cascade c's square: a draw over the whole map with
    // that square as its scissor (the hardware shadow pass) draws the cascade.
    glm::mat4 mapClip(std::uint32_t c) const;
    // Cascade c's square in texels of a map `mapSize` a side.
    VkRect2D texels(std::uint32_t c, std::uint32_t mapSize) const;
};

// The cascades for a camera: `count` (1 to kMostShadowCascades) stretches of the view from the nearest
// point that can be shadowed (the crowd's near edge, or the near plane inside it) out to the shadow
// distance (the crowd's far edge, at most 60 character heights), split half logarithmically, half
// evenly (the "practical" split), each looking along `towardsLight` and extended towards the light to
// hold the casters above it. One cascade is the whole map over the whole view, as before cascades.
ShadowCascades shadowCascades(const Camera& camera, float aspect, const CrowdShape& crowd, const glm::vec3& towardsLight,
                              std::uint32_t count, std::uint32_t mapSize);

// The cascade whose shadow a point takes (its stretch's, or the next if that one does not own it), or
// -1: lit.
int cascadeHolding(const ShadowCascades& cascades, const glm::vec3& world);

}  // namespace render
