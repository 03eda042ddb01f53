#include "anim/soa_palette_job.h"

#include "anim/soa_maths.h"

namespace anim {

bool SoaPaletteJob::validate() const {
    if (!library || model >= library->modelCount()) return false;
    const std::uint32_t joints = library->jointCount(model);
    return locals.size() >= soaGroups(joints) && scratch.size() >= joints && output.size() >= joints;
}

template <class F>
void SoaPaletteJob::runWith() const {
    const gpu::AnimationModel& m = library->models()[model];
    const gpu::AnimationJoint* joints = library->joints().data() + m.info.x;
    const soa::Rows<F> top = soa::compose(soa::loadRows<F>(placement), soa::loadRows<F>(m.root));
    for (std::uint32_t g = 0; g < soaGroups(m.info.y); ++g) {
        soa::Rows<F> local[kSoaLanes];
        soa::affinesOf<F>(locals[g], local);
        for (std::uint32_t lane = 0; lane < kSoaLanes; ++lane) {
            const std::uint32_t j = g * kSoaLanes + lane;
            if (j >= m.info.y) break;
            const int parent = static_cast<int>(joints[j].restTranslation.w);
            const soa::Rows<F> above = parent < 0 ? top : soa::loadRows<F>(scratch[static_cast<std::uint32_t>(parent)]);
            const soa::Rows<F> world = soa::compose(above, local[lane]);
            soa::storeRows(world, scratch[j]);
            soa::storeRows(soa::compose(world, soa::loadRows<F>(joints[j].inverseBind)), output[j]);
        }
    }
}

void SoaPaletteJob::run() const { runWith<simd::NativeFloat4>(); }

template void SoaPaletteJob::runWith<simd::LaneFloat4>() const;
#ifdef CROWD_ANIM_HAVE_SSE2
template void SoaPaletteJob::runWith<simd::Sse2Float4>() const;
#endif

}  // namespace anim
