#include "anim/palette_job.h"

namespace anim {

bool PaletteJob::validate() const {
    if (!library || model >= library->modelCount()) return false;
    const std::uint32_t joints = library->jointCount(model);
    return locals.size() == joints && scratch.size() >= joints && output.size() >= joints;
}

void PaletteJob::run() const {
    const gpu::AnimationModel& m = library->models()[model];
    const Affine top = compose(placement, m.root);
    for (std::uint32_t j = 0; j < m.info.y; ++j) {
        const gpu::AnimationJoint& joint = library->joints()[m.info.x + j];
        const int parent = static_cast<int>(joint.restTranslation.w);
        scratch[j] = compose(parent < 0 ? top : scratch[static_cast<std::uint32_t>(parent)], affineOf(locals[j]));
        output[j] = compose(scratch[j], joint.inverseBind);
    }
}

}  // namespace anim
