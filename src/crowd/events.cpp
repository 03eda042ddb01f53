#include "crowd/events.h"

#include <algorithm>
#include <cmath>

namespace crowd {
namespace {

// The segment's phase in double (motionPhase's formula, with Segment::rate's exact rate), and its
// inverse: d(phase)/dt rises linearly from the from-clip's rate to the to-clip's over the crossfade,
// then stays. Rates are never negative, so the phase never decreases.
struct PhaseCurve {
    double start, phase0, rateFrom, rateTo, fade;

    double at(double elapsed) const {
        if (fade > 0.0 && elapsed < fade) return phase0 + rateFrom * elapsed + (rateTo - rateFrom) * elapsed * elapsed / (2.0 * fade);
        const double faded = fade > 0.0 ? 0.5 * (rateFrom + rateTo) * fade : 0.0;
        return phase0 + faded + rateTo * (elapsed - std::max(fade, 0.0));
    }
    // The elapsed time at which the phase reaches `target` (>= at(0)), or a negative value if never.
    double when(double target) const {
        const double d = target - phase0;
        if (fade > 0.0) {
            const double fadeEnd = at(fade);
            if (target <= fadeEnd) {
                // a e^2 + b e = d; the root in [0, fade], in the form that stays exact when a is 0.
                const double a = (rateTo - rateFrom) / (2.0 * fade), b = rateFrom;
                const double root = std::sqrt(std::max(b * b + 4.0 * a * d, 0.0));
                return b + root > 0.0 ? 2.0 * d / (b + root) : -1.0;
            }
            return rateTo > 0.0 ? fade + (target - fadeEnd) / rateTo : -1.0;
        }
        return rateTo > 0.0 ? d / rateTo : -1.0;
    }
};

}  // namespace

void segmentEvents(const Segment& segment, const model::SkinnedModel& model, const anim::ClipLibrary& library,
                   std::uint32_t modelIndex, std::uint32_t character, double begin, double end, double from,
                   double to, std::vector<FiredEvent>& out) {
    const double lo = std::max(from, begin), hi = std::min(to, end);
    if (!(hi >= lo) || model.clips.empty()) return;
    const gpu::MotionRecord& m = segment.motion;
    const PhaseCurve curve{segment.start, m.phase.x, m.phase.y, segment.rate != 0.0 ? segment.rate : m.phase.z,
                           m.timing.y};
    const double first = curve.at(std::max(lo - segment.start, 0.0)), last = curve.at(std::max(hi - segment.start, 0.0));
    const std::uint32_t clipFrom = m.clips.x, clipTo = m.clips.y;
    const std::size_t mark = out.size();
    const std::uint32_t clips[2] = {clipTo, clipFrom};
    for (std::uint32_t i = 0; i < (clipFrom == clipTo ? 1u : 2u); ++i) {
        const std::uint32_t clip = clips[i];
        const anim::Clip& c = model.clips[clip];
        const float duration = library.duration(modelIndex, clip);
        if (!(duration > 0.0f)) continue;
        for (std::uint32_t e = 0; e < c.events.size(); ++e) {
            const double point = static_cast<double>(c.events[e].time) / duration;  // in cycles
            // Every crossing of point + k between the window's phases (one either side for rounding;
            // the times decide).
            for (double k = std::floor(first - point) - 1.0; k <= std::ceil(last - point) + 1.0; k += 1.0) {
                const double elapsed = curve.when(point + k);
                if (elapsed < 0.0) continue;
                const double t = segment.start + elapsed;
                if (!(t > from && t <= to && t >= begin && t < end)) continue;
                // The clip of the larger weight fires (the one faded to from half way on).
                const bool toWins = !(curve.fade > 0.0) || elapsed >= 0.5 * curve.fade;
                if (clipFrom != clipTo && (clip == clipTo) != toWins) continue;
                out.push_back({character, clip, e, t});
            }
        }
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(mark), out.end(),
              [](const FiredEvent& a, const FiredEvent& b) { return a.time < b.time || (a.time == b.time && a.event < b.event); });
}

}  // namespace crowd
