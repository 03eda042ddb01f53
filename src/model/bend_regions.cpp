#include "model/bend_regions.h"

#include <algorithm>
#include <cmath>

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"

namespace model {
namespace {

constexpr int kSamplesPerClip = 32;

// The angle of the rotation in an affine matrix (its scale divided out).
float rotationAngle(const glm::mat4& m) {
    const glm::mat3 r(glm::normalize(glm::vec3(m[0])), glm::normalize(glm::vec3(m[1])), glm::normalize(glm::vec3(m[2])));
    return std::acos(std::clamp((r[0][0] + r[1][1] + r[2][2] - 1.0f) * 0.5f, -1.0f, 1.0f));
}

// Raises bend[j] to how far each bone turns against its parent's in one pose. A bone's skinning matrix
// (model space times inverse bind) is where the pose has moved it from the bind pose; two bones that
// keep their bind angle have equal rotations in theirs.
void measurePose(const SkinnedModel& model, const std::vector<anim::Transform>& locals, std::vector<float>& bend) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<glm::mat4> skinning(skeleton.jointCount());
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, skinning);
    for (std::size_t j = 0; j < skinning.size(); ++j) skinning[j] = skinning[j] * skeleton.inverseBind[j];
    for (std::size_t j = 0; j < skinning.size(); ++j)
        if (const std::int32_t parent = skeleton.parents[j]; parent >= 0)
            bend[j] = std::max(bend[j], rotationAngle(glm::inverse(skinning[parent]) * skinning[j]));
}

}  // namespace

std::vector<std::uint32_t> bendRegions(const SkinnedModel& model) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<float> bend(skeleton.jointCount(), 0.0f);
    measurePose(model, skeleton.restPose, bend);
    std::vector<anim::Transform> locals(skeleton.restPose);
    for (const anim::Clip& clip : model.clips)
        for (int i = 0; i < kSamplesPerClip; ++i) {
            anim::sampleClip(clip, clip.duration * static_cast<float>(i) / kSamplesPerClip, skeleton.restPose, locals);
            measurePose(model, locals, bend);
        }
    // parents[j] < j: one forward sweep finds every region head.
    std::vector<std::uint32_t> head(skeleton.jointCount());
    for (std::uint32_t j = 0; j < head.size(); ++j) {
        const std::int32_t parent = skeleton.parents[j];
        head[j] = parent < 0 || bend[j] >= kMinBendRadians ? j : head[static_cast<std::size_t>(parent)];
    }
    return head;
}

}  // namespace model
