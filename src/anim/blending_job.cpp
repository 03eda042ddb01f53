#include "anim/blending_job.h"

namespace anim {

glm::quat nlerpShortest(const glm::quat& a, const glm::quat& b, float weight) {
    const glm::quat near = glm::dot(a, b) < 0.0f ? -b : b;
    return glm::normalize(a * (1.0f - weight) + near * weight);
}

void BlendingJob::run() const {
    for (std::size_t j = 0; j < output.size(); ++j) {
        const Transform& a = from[j];
        const Transform& b = to[j];
        output[j] = {glm::mix(a.translation, b.translation, weight), nlerpShortest(a.rotation, b.rotation, weight),
                     glm::mix(a.scale, b.scale, weight)};
    }
}

}  // namespace anim
