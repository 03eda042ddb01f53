#pragma once
// The epoch of the GPU's clock. Scene time is a double on the CPU, but the GPU (and the CPU reference
// that repeats its arithmetic) evaluates motion in float: at 1e6 s a float steps in 62.5 ms, at 1e7 s in
// a whole second. So the GPU never sees scene time: it gets the frame's time less an epoch, a whole
// multiple of kEpochSeconds at or below it, and every segment relative to the same epoch
// (crowd/segment.h). Those floats stay under kEpochSeconds plus a crossfade, where they step in under
// 8 microseconds at any scene time. Entering the next epoch restates every segment: one full upload of
// the segments every kEpochSeconds.
#include <cmath>

#include "gpu_types.h"

namespace crowd {

inline constexpr double kEpochSeconds = EPOCH_SECONDS;

inline double epochOf(double time) { return std::floor(time / kEpochSeconds) * kEpochSeconds; }

}  // namespace crowd
