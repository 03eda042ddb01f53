#pragma once
// A prop becomes part of its model: a rigid part of the skinned mesh on a joint of its own, a child of
// the joint it is attached to, whose rest transform is the offset. Its vertices are placed in bind
// space at bindWorld(joint) * offset * local, weighted 1 to that joint, so skinning gives
// jointWorld * offset * local exactly and culling, levels of detail, shadows, fades and impostors draw
// it with the character, with no pass of their own. Levels of detail must be (re)built afterwards:
// buildLods draws the prop's own levels (PropMesh::levels) beside the body's simplified ones.
#include <string>

#include <glm/glm.hpp>

#include "model/prop_mesh.h"
#include "model/skinned_model.h"

namespace model {

// Attaches `prop` to the joint named `joint` with `offset` (the prop's space to the joint's: a
// rotation, a uniform scale and a translation) as prop number model.props.size(). `share`: the part of a
// crowd that carries it when characters do not choose (0..1). Throws gpu::Error naming the model and
// the joint when the model has no such joint, and for an offset that is not a rotation with a uniform
// scale, a share outside [0, 1], more than MAX_PROPS props, too many materials, or a mesh checkPropMesh
// refuses.
void attachProp(SkinnedModel& model, const PropMesh& prop, const std::string& joint, const glm::mat4& offset,
                float share = 1.0f);

// The props at least half of a crowd carries by default (share >= 0.5): the ones the model's pose
// sphere holds and its impostors show (docs/props.md, "What a rare prop gives up").
std::uint32_t propsMostCarry(const SkinnedModel& model);
// Whether vertex `v` belongs to a prop outside `carried`.
bool onPropLeftOut(const SkinnedModel& model, const gpu::SkinVertex& v, std::uint32_t carried);

// The props a character carries when it does not choose: prop k when a hash of (seed, character, k)
// falls below its share, so a crowd gets the same carriers every run.
std::uint32_t defaultPropsCarried(const SkinnedModel& model, std::uint32_t seed, std::uint32_t character);

}  // namespace model
