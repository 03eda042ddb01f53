#include "anim/local_to_model.h"

#include <cassert>

namespace anim {

void localToModel(std::span<const std::int32_t> parents, std::span<const Transform> locals,
                  const glm::mat4& rootTransform, std::span<glm::mat4> out) {
    assert(parents.size() == locals.size() && out.size() == locals.size());
    for (std::size_t i = 0; i < locals.size(); ++i) {
        const std::int32_t parent = parents[i];
        assert(parent < static_cast<std::int32_t>(i));
        const glm::mat4& above = parent < 0 ? rootTransform : out[static_cast<std::size_t>(parent)];
        out[i] = above * locals[i].matrix();
    }
}

}  // namespace anim
