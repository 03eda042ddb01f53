#pragma once
// A prop: a rigid mesh that a model carries on a joint (a rifle in the hand, a flag), in its own space.
#include <string>
#include <vector>

#include "gpu_types.h"
#include "model/skinned_model.h"

namespace model {

// Vertices as the model's (bind-pose SkinVertex, material index in normal.w), all rigid on joint 0:
// attachProp moves them to the joint it gives the prop. Materials index materialColors.
struct PropMesh {
    std::string name;
    std::vector<gpu::SkinVertex> vertices;
    std::vector<std::uint32_t> indices;  // counter-clockwise triangles
    std::vector<glm::vec4> materialColors;
};

// The built-in props, in metres. The rifle lies along +z (muzzle forward), its grip at the origin where
// a hand closes on it; the flag's pole runs along +y from the origin, where a hand holds it.
PropMesh makeRifle();
PropMesh makeFlag();

// The mesh of a model with one rigid part (a prop made in code or read from a file): every vertex
// must be on joint 0 alone.
PropMesh propFromModel(const SkinnedModel& model);

}  // namespace model
