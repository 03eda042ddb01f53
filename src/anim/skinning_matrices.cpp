#include "anim/skinning_matrices.h"

#include <cassert>

#include <glm/gtc/matrix_access.hpp>

namespace anim {

gpu::BoneRows toRows(const glm::mat4& m) {
    return {glm::row(m, 0), glm::row(m, 1), glm::row(m, 2)};
}

glm::mat4 fromRows(const gpu::BoneRows& rows) {
    glm::mat4 m(1.0f);
    m = glm::row(m, 0, rows.row0);
    m = glm::row(m, 1, rows.row1);
    m = glm::row(m, 2, rows.row2);
    return m;
}

void skinningMatrices(std::span<const glm::mat4> model, std::span<const glm::mat4> inverseBind,
                      const glm::mat4& world, std::span<gpu::BoneRows> out) {
    assert(model.size() == inverseBind.size() && out.size() >= model.size());
    for (std::size_t i = 0; i < model.size(); ++i) out[i] = toRows(world * model[i] * inverseBind[i]);
}

}  // namespace anim
