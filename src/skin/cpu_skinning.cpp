#include "skin/cpu_skinning.h"

namespace skin {
namespace {

glm::dvec3 transformPoint(const gpu::BoneRows& b, const glm::dvec3& p) {
    const glm::dvec4 q(p, 1.0);
    return {glm::dot(glm::dvec4(b.row0), q), glm::dot(glm::dvec4(b.row1), q), glm::dot(glm::dvec4(b.row2), q)};
}

glm::dvec3 transformDirection(const gpu::BoneRows& b, const glm::dvec3& d) {
    return {glm::dot(glm::dvec3(b.row0), d), glm::dot(glm::dvec3(b.row1), d), glm::dot(glm::dvec3(b.row2), d)};
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
        out[i] = {position, glm::normalize(normal)};
    }
    return out;
}

}  // namespace skin
