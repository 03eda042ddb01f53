#pragma once
// Which joints move a vertex, and how much: the skinning half of a SkinVertex.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace model {

// Up to four joints with weights summing to 1; unused slots hold joint 0 with weight 0.
struct Influences {
    glm::uvec4 joints{0u};
    glm::vec4 weights{0.0f};
};

// A vertex moved by one joint alone (props, rigid parts).
Influences rigid(std::uint32_t joint);

// A chain of joints along a limb or a spine, in hierarchy order, with their bind positions.
// Bone k is the stretch from joint k towards joint k + 1; the last bone runs on past its joint.
struct BoneChain {
    std::span<const std::uint32_t> joints;
    std::span<const glm::vec3> positions;
};

// Influences of a point on a chain: it follows the bone it projects onto, but within `band` metres
// of an interior joint it blends smoothly from the parent bone to the child bone, so skin bends
// round a knee instead of tearing at it. The band shrinks on short bones so blends never overlap.
Influences chainInfluences(const BoneChain& chain, const glm::vec3& point, float band);

}  // namespace model
