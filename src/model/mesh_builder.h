#pragma once
// Builds a skinned mesh from closed parts (tapered tubes and boxes), each rigged to joints.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "model/influences.h"
#include "model/skinned_model.h"

namespace model {

// One cross-section of a tube: an ellipse around `center` in the plane across the tube.
struct Ring {
    glm::vec3 center{0.0f};
    glm::vec2 radius{0.0f};  // x: along the tube's side direction, y: across it
    std::uint32_t material = 0;
};

// A closed tube through its rings, the shape of limbs, bodies and heads. An end ring of zero radius
// closes the tube to a point (a rounded end); any other end ring gets a flat cap. The band between
// two rings takes the material of the first, so a colour edge (a boot top) is exactly at a ring.
struct Tube {
    std::vector<Ring> rings;
    // Direction of radius.x; projected across the tube at each ring, so it must never run along it.
    glm::vec3 side{1.0f, 0.0f, 0.0f};
    int segments = 8;
    // Influences of a ring's vertices, from the ring's centre.
    std::function<Influences(const glm::vec3& center)> skin;
};

// A flat-shaded box (rifle parts, packs): centre, half sizes along its right-handed axes.
struct Box {
    glm::vec3 center{0.0f};
    glm::vec3 halfExtent{0.0f};
    glm::mat3 axes{1.0f};
    std::uint32_t material = 0;
    Influences skin;
};

// A tube skin that blends along a chain of joints (see chainInfluences).
std::function<Influences(const glm::vec3&)> chainSkin(std::vector<std::uint32_t> joints,
                                                      std::vector<glm::vec3> positions, float band);
// A tube skin that follows one joint alone (a head, a helmet).
std::function<Influences(const glm::vec3&)> rigidSkin(std::uint32_t joint);

// Append a part's vertices and counter-clockwise triangles to the model. Tube normals are the
// area-weighted average of the faces round each vertex, so they are smooth across the tube.
void addTube(SkinnedModel& model, const Tube& tube);
void addBox(SkinnedModel& model, const Box& box);

// Scales the bind-pose vertices per axis (a seed's proportions), keeping normals perpendicular.
void stretchVertices(SkinnedModel& model, glm::vec3 stretch);

}  // namespace model
