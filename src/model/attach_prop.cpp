#include "model/attach_prop.h"

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "gpu/error.h"
#include "model/seeded_variation.h"

namespace model {
namespace {

std::int32_t jointNamed(const anim::Skeleton& skeleton, const std::string& name) {
    for (std::size_t j = 0; j < skeleton.jointNames.size(); ++j)
        if (skeleton.jointNames[j] == name) return static_cast<std::int32_t>(j);
    return -1;
}

// The offset as a joint's rest transform. Skinning maps normals with a bone's 3x3 part, which is
// right only for rotations with a uniform scale (shaders/skinning.glsl.inc): anything else is refused.
anim::Transform restTransformOf(const glm::mat4& offset, const std::string& what) {
    const glm::mat3 m(offset);
    const float scale = glm::length(m[0]);
    const float tolerance = 1e-4f * scale;
    const bool uniform = std::abs(glm::length(m[1]) - scale) <= tolerance && std::abs(glm::length(m[2]) - scale) <= tolerance;
    const bool orthogonal = std::abs(glm::dot(m[0], m[1])) <= tolerance * scale &&
                            std::abs(glm::dot(m[0], m[2])) <= tolerance * scale &&
                            std::abs(glm::dot(m[1], m[2])) <= tolerance * scale;
    const bool affine = offset[0][3] == 0.0f && offset[1][3] == 0.0f && offset[2][3] == 0.0f && offset[3][3] == 1.0f;
    if (!(scale > 0.0f) || !std::isfinite(scale) || !uniform || !orthogonal || !affine || glm::determinant(m) <= 0.0f)
        throw gpu::Error(what + ": the offset must be a rotation, a uniform scale and a translation");
    anim::Transform rest;
    rest.translation = glm::vec3(offset[3]);
    rest.rotation = glm::normalize(glm::quat_cast(m / scale));
    rest.scale = glm::vec3(scale);
    return rest;
}

// The model's material index for a colour, appending it when new.
std::uint32_t materialFor(SkinnedModel& model, const glm::vec4& colour, const std::string& what) {
    for (std::size_t m = 0; m < model.materialColors.size(); ++m)
        if (model.materialColors[m] == colour && !(model.texturedMaterials >> m & 1u)) return static_cast<std::uint32_t>(m);
    if (model.materialColors.size() >= MAX_MODEL_MATERIALS)
        throw gpu::Error(what + ": the model would have more than " + std::to_string(MAX_MODEL_MATERIALS) + " materials");
    model.materialColors.push_back(colour);
    return static_cast<std::uint32_t>(model.materialColors.size() - 1);
}

std::string uniqueJointName(const anim::Skeleton& skeleton, const std::string& name) {
    std::string candidate = name;
    for (int n = 2; jointNamed(skeleton, candidate) >= 0; ++n) candidate = name + "_" + std::to_string(n);
    return candidate;
}

}  // namespace

void attachProp(SkinnedModel& model, const PropMesh& prop, const std::string& joint, const glm::mat4& offset,
                float share) {
    const std::string what = model.name + ": prop '" + prop.name + "' on joint '" + joint + "'";
    checkPropMesh(prop, what);
    const std::int32_t parent = jointNamed(model.skeleton, joint);
    if (parent < 0) throw gpu::Error(model.name + " has no joint '" + joint + "' to carry prop '" + prop.name + "'");
    if (!(share >= 0.0f && share <= 1.0f)) throw gpu::Error(what + ": its share must be within [0, 1]");
    if (model.props.size() >= MAX_PROPS)
        throw gpu::Error(what + ": a model carries at most " + std::to_string(MAX_PROPS) + " props");
    if (model.skeleton.jointCount() >= MAX_ANIMATION_JOINTS)
        throw gpu::Error(what + ": the model has no room for the prop's joint (" + std::to_string(MAX_ANIMATION_JOINTS) +
                         " joints at most)");
    anim::Skeleton& skeleton = model.skeleton;
    const anim::Transform rest = restTransformOf(offset, what);
    // The prop's own joint, a child of `joint` at the offset: its world transform is jointWorld * offset.
    const glm::mat4 jointBind = glm::inverse(skeleton.inverseBind[static_cast<std::size_t>(parent)]);
    const glm::mat4 propBind = jointBind * offset;
    const auto propJoint = static_cast<std::uint32_t>(skeleton.jointCount());
    skeleton.propOfJoint.resize(skeleton.jointCount(), 0u);
    skeleton.jointNames.push_back(uniqueJointName(skeleton, prop.name));
    skeleton.parents.push_back(parent);
    skeleton.restPose.push_back(rest);
    skeleton.inverseBind.push_back(glm::inverse(propBind));
    skeleton.propOfJoint.push_back(static_cast<std::uint32_t>(model.props.size()) + 1u);
    model.props.push_back({prop.name, propJoint, static_cast<std::uint32_t>(parent), share, {}});

    std::vector<std::uint32_t> materials;
    for (const glm::vec4& colour : prop.materialColors) materials.push_back(materialFor(model, colour, what));
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(propBind)));
    const auto first = static_cast<std::uint32_t>(model.vertices.size());
    for (const gpu::SkinVertex& local : prop.vertices) {
        gpu::SkinVertex v{};
        v.position = glm::vec4(glm::vec3(propBind * glm::vec4(glm::vec3(local.position), 1.0f)), 1.0f);
        const auto material = static_cast<std::size_t>(local.normal.w);
        if (material >= materials.size()) throw gpu::Error(what + ": a vertex names material " + std::to_string(material) +
                                                           " of " + std::to_string(materials.size()));
        v.normal = glm::vec4(glm::normalize(normalMatrix * glm::vec3(local.normal)), static_cast<float>(materials[material]));
        v.joints = glm::uvec4(propJoint, 0u, 0u, 0u);
        v.weights = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        model.vertices.push_back(v);
    }
    if (!model.uvs.empty()) model.uvs.resize(model.vertices.size(), glm::vec2(0.0f));
    // Level 0 joins the model's full mesh; the coarser levels wait for buildLods, which draws them
    // beside the body's simplified levels.
    for (std::uint32_t index : prop.levels[0]) model.indices.push_back(first + index);
    for (std::size_t l = 1; l < kLodLevels; ++l)
        for (std::uint32_t index : prop.levels[l]) model.props.back().coarserLevels[l - 1].push_back(first + index);
    model.lods.clear();  // the mesh changed: levels are built again (model/lod_builder.h)
    computeBounds(model);
}

std::uint32_t propsMostCarry(const SkinnedModel& model) {
    std::uint32_t carried = 0;
    for (std::size_t k = 0; k < model.props.size(); ++k)
        if (model.props[k].share >= 0.5f) carried |= 1u << k;
    return carried;
}

bool onPropLeftOut(const SkinnedModel& model, const gpu::SkinVertex& v, std::uint32_t carried) {
    const std::vector<std::uint32_t>& propOfJoint = model.skeleton.propOfJoint;
    if (v.joints.x >= propOfJoint.size() || propOfJoint[v.joints.x] == 0u) return false;
    return (carried >> (propOfJoint[v.joints.x] - 1u) & 1u) == 0u;
}

std::uint32_t defaultPropsCarried(const SkinnedModel& model, std::uint32_t seed, std::uint32_t character) {
    std::uint32_t carried = 0;
    for (std::size_t k = 0; k < model.props.size(); ++k) {
        // seededUnit is in [-1, 1]: its half plus a half is uniform in [0, 1].
        const float draw = 0.5f + 0.5f * seededUnit(seed ^ (character * 0x27D4EB2Fu), 0x50524F50u + static_cast<std::uint32_t>(k));
        if (draw < model.props[k].share || model.props[k].share >= 1.0f) carried |= 1u << k;
    }
    return carried;
}

}  // namespace model
