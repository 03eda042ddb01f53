#include "anim/soa_blending_job.h"

#include "anim/soa_maths.h"

namespace anim {

template <class F>
void SoaBlendingJob::runWith() const {
    const F w = F::splat(weight);
    for (std::size_t g = 0; g < output.size(); ++g) {
        const SoaTransform& a = from[g];
        const SoaTransform& b = to[g];
        // Everything is read before anything is written: the output may alias either input.
        const soa::Vec3<F> translation = soa::mix(soa::load<F>(a.translation), soa::load<F>(b.translation), w);
        const soa::Quat<F> rotation = soa::nlerpShortest(soa::load<F>(a.rotation), soa::load<F>(b.rotation), w);
        const soa::Vec3<F> scale = soa::mix(soa::load<F>(a.scale), soa::load<F>(b.scale), w);
        soa::store(translation, output[g].translation);
        soa::store(rotation, output[g].rotation);
        soa::store(scale, output[g].scale);
    }
}

void SoaBlendingJob::run() const { runWith<simd::NativeFloat4>(); }

template void SoaBlendingJob::runWith<simd::LaneFloat4>() const;
#ifdef CROWD_ANIM_HAVE_SSE2
template void SoaBlendingJob::runWith<simd::Sse2Float4>() const;
#endif

}  // namespace anim
