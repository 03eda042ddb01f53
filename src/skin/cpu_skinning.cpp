#include "skin/cpu_skinning.h"

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"
#include "anim/skinning_matrices.h"

#include <cmath>

namespace skin {
namespace {

glm::dvec3 transformPoint(const gpu::BoneRows& b, const glm::dvec3& p) {
    const glm::dvec4 q(p, 1.0);
    return {glm::dot(glm::dvec4(b.row0), q), glm::dot(glm::dvec4(b.row1), q), glm::dot(glm::dvec4(b.row2), q)};
}

glm::dvec3 transformDirection(const gpu::BoneRows& b, const glm::dvec3& d) {
    return {glm::dot(glm::dvec3(b.row0), d), glm::dot(glm::dvec3(b.row1), d), glm::dot(glm::dvec3(b.row2), d)};
}

// The blended normal made unit length; a collapsed one (its bones scale it to nothing) keeps the bind
// normal, as the shaders do (shaders/skinning.glsl.inc).
glm::dvec3 unitNormal(const glm::dvec3& skinned, const glm::dvec3& bind) {
    const double length2 = glm::dot(skinned, skinned);
    return length2 > COLLAPSED_NORMAL_LENGTH2 ? skinned / std::sqrt(length2) : bind;
}

}  // namespace

std::vector<CpuSkinnedVertex> skinOnCpu(const model::SkinnedModel& model, std::span<const gpu::BoneRows> bones) {
    std::vector<CpuSkinnedVertex> out(model.vertices.size());
    for (std::size_t i = 0; i < model.vertices.size(); ++i) {
        const gpu::SkinVertex& v = model.vertices[i];
        glm::dvec3 position(0.0), normal(0.0);
        for (int k = 0; k < MAX_INFLUENCES; ++k) {
            const double weight = v.weights[k];
            if (weight == 0.0) continue;
            const gpu::BoneRows& bone = bones[v.joints[k]];
            position += weight * transformPoint(bone, glm::dvec3(v.position));
            normal += weight * transformDirection(bone, glm::dvec3(v.normal));
        }
        out[i] = {position, unitNormal(normal, glm::dvec3(v.normal))};
    }
    return out;
}

std::vector<CpuSkinnedVertex> morphOnCpu(const std::vector<CpuSkinnedVertex>& skinned,
                                         const std::vector<model::LodMorphTarget>& targets, std::uint32_t firstMoving,
                                         double share) {
    std::vector<CpuSkinnedVertex> out = skinned;
    for (std::size_t v = firstMoving; v < skinned.size(); ++v) {
        const model::LodMorphTarget& t = targets[v];
        const double w[3] = {1.0 - double(t.weights.x) - double(t.weights.y), t.weights.x, t.weights.y};
        glm::dvec3 position(0.0), normal(0.0);
        for (int k = 0; k < 3; ++k) {
            position += w[k] * skinned[t.corners[k]].position;
            normal += w[k] * skinned[t.corners[k]].normal;
        }
        out[v].position = skinned[v].position + share * (position - skinned[v].position);
        out[v].normal = unitNormal(skinned[v].normal + share * (normal - skinned[v].normal), skinned[v].normal);
    }
    return out;
}

std::vector<CpuSkinnedVertex> poseOnCpu(const model::SkinnedModel& model, std::uint32_t clip, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.restPose);
    if (clip < model.clips.size()) anim::sampleClip(model.clips[clip], time, skeleton.restPose, locals);
    std::vector<glm::mat4> modelSpace(skeleton.jointCount());
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, modelSpace);
    std::vector<gpu::BoneRows> bones(skeleton.jointCount());
    anim::skinningMatrices(modelSpace, skeleton.inverseBind, glm::mat4(1.0f), bones);
    return skinOnCpu(model, bones);
}

}  // namespace skin
