#include "model/clip_skinning.h"

#include "anim/local_to_model.h"
#include "anim/sample_clip.h"

namespace model {

std::vector<glm::mat4> clipSkinningMatrices(const SkinnedModel& model, const anim::Clip& clip, float time) {
    const anim::Skeleton& skeleton = model.skeleton;
    std::vector<anim::Transform> locals(skeleton.jointCount());
    std::vector<glm::mat4> global(skeleton.jointCount());
    anim::sampleClip(clip, time, skeleton.restPose, locals);
    anim::localToModel(skeleton.parents, locals, skeleton.rootTransform, global);
    for (std::size_t j = 0; j < global.size(); ++j) global[j] = global[j] * skeleton.inverseBind[j];
    return global;
}

}  // namespace model
