#include "crowd/events.h"

#include <algorithm>
#include <cmath>

#include "crowd/event_pairs.h"
#include "gpu/error.h"

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
    // The first elapsed time at which the phase meets `target + drift * weight` (the weight rising
    // from 0 to 1 over the crossfade), or a negative value if never or if it had already met it at the
    // start (it fired before this segment). Drift 0: where the phase reaches `target`. With a drift the
    // phase less the moving point can rise, fall and rise again through the fade (when the drift
    // exceeds the fade times the slower rate): the point is met first, then passed back and met
    // again; it fires once, at the first meeting.
    double when(double target, double drift = 0.0) const {
        const double d = target - phase0;
        if (fade > 0.0) {
            if (d < 0.0) return -1.0;
            // a e^2 + b e = d through the fade. Its first root in [0, fade], in the form that stays
            // exact when a is 0: with d >= 0 the first non-negative root is 2d / (b + sqrt(b^2 + 4ad))
            // whenever it exists (disc >= 0 and b + sqrt > 0).
            const double a = (rateTo - rateFrom) / (2.0 * fade), b = rateFrom - drift / fade;
            const double fadeEnd = at(fade) - drift;  // the phase less the point at the fade's end
            const double disc = b * b + 4.0 * a * d;
            if (target <= fadeEnd) {
                // Met by the end of the fade (the phase less the point is continuous): rounding aside,
                // disc >= 0.
                const double root = std::sqrt(std::max(disc, 0.0));
                return b + root > 0.0 ? 2.0 * d / (b + root) : -1.0;
            }
            if (disc >= 0.0) {
                // Met inside the fade and passed back before its end.
                const double root = std::sqrt(disc);
                if (b + root > 0.0 && 2.0 * d / (b + root) <= fade) return 2.0 * d / (b + root);
            }
            return rateTo > 0.0 ? fade + (target - fadeEnd) / rateTo : -1.0;
        }
        return rateTo > 0.0 ? d / rateTo : -1.0;
    }
};

}  // namespace

void segmentEvents(const Segment& segment, const model::SkinnedModel& model, const anim::ClipLibrary& library,
                   std::uint32_t modelIndex, std::uint32_t character, double begin, double end, double from,
                   double to, EventSink& out) {
    const double lo = std::max(from, begin), hi = std::min(to, end);
    if (!(hi >= lo) || model.clips.empty()) return;
    const gpu::MotionRecord& m = segment.motion;
    const PhaseCurve curve{segment.start, m.phase.x, m.phase.y, segment.rate != 0.0 ? segment.rate : m.phase.z,
                           m.timing.y};
    const double first = curve.at(std::max(lo - segment.start, 0.0)), last = curve.at(std::max(hi - segment.start, 0.0));
    const std::uint32_t clipFrom = m.clips.x, clipTo = m.clips.y;
    const std::size_t mark = out.kept ? out.kept->size() : 0;
    // Kept while there is room; counted always.
    auto fire = [&](const FiredEvent& event) {
        if (out.kept && out.count < out.room) out.kept->push_back(event);
        ++out.count;
    };
    // Pairs need a crossfade of two clips that both have events and a length (a clip of none fires
    // nothing); most fades (to and from a standing clip with no events) skip the search.
    const float fromDuration = library.duration(modelIndex, clipFrom);
    const bool pairing = clipFrom != clipTo && curve.fade > 0.0 && !model.clips[clipFrom].events.empty() &&
                         !model.clips[clipTo].events.empty() && fromDuration > 0.0f && library.duration(modelIndex, clipTo) > 0.0f;
    const std::uint32_t clips[2] = {clipTo, clipFrom};
    for (std::uint32_t i = 0; i < (clipFrom == clipTo ? 1u : 2u); ++i) {
        const std::uint32_t clip = clips[i];
        const anim::Clip& c = model.clips[clip];
        const float duration = library.duration(modelIndex, clip);
        if (!(duration > 0.0f)) continue;
        for (std::uint32_t e = 0; e < c.events.size(); ++e) {
            // A paired event (crowd/event_pairs.h) fires once, from its to-clip's side, where the
            // phase meets the point blended by the weight; an unpaired one fires from its clip while
            // that clip weighs more (the one faded to from half way on).
            std::int32_t partner = -1;
            if (pairing) {
                if (clip == clipFrom && hasPartner(c, e, model.clips[clipTo])) continue;
                if (clip == clipTo) partner = pairedEvent(model.clips[clipFrom], c, e);
            }
            const double point = static_cast<double>(c.events[e].time) / duration;  // in cycles
            const BlendedPoint blend =
                partner >= 0 ? blendedPoint(static_cast<double>(model.clips[clipFrom].events[partner].time) / fromDuration, point)
                             : BlendedPoint{point, 0.0};
            // Every meeting of blend.base + k between the window's phases less the point's drift (it
            // lies between 0 and blend.drift), one more either side for rounding: the times decide.
            const double kFirst = std::floor(first - std::max(blend.drift, 0.0) - blend.base) - 1.0;
            const double kLast = std::ceil(last - std::min(blend.drift, 0.0) - blend.base) + 1.0;
            // Counted in integers: past 2^53 cycles k + 1 == k, and a double loop would never end.
            if (!(kLast - kFirst <= kMostCyclesInWindow))
                throw gpu::Error("character " + std::to_string(character) + ": its clip " + std::to_string(clip) +
                                 " loops more than " + std::to_string(static_cast<long>(kMostCyclesInWindow)) +
                                 " times in the window (ask for shorter windows)");
            const auto cycles = static_cast<std::int64_t>(kLast - kFirst);
            for (std::int64_t n = 0; n <= cycles; ++n) {
                const double k = kFirst + static_cast<double>(n);
                const double elapsed = curve.when(blend.base + k, blend.drift);
                if (elapsed < 0.0) continue;
                const double t = segment.start + elapsed;
                if (!(t > from && t <= to && t >= begin && t < end)) continue;
                const bool toWins = !(curve.fade > 0.0) || elapsed >= 0.5 * curve.fade;
                if (partner >= 0) {
                    // The pair is reported as the event of the clip that weighs more then.
                    fire(toWins ? FiredEvent{character, clipTo, e, t}
                                : FiredEvent{character, clipFrom, static_cast<std::uint32_t>(partner), t});
                    continue;
                }
                if (clipFrom != clipTo && (clip == clipTo) != toWins) continue;
                fire({character, clip, e, t});
            }
        }
    }
    if (!out.kept) return;
    std::sort(out.kept->begin() + static_cast<std::ptrdiff_t>(mark), out.kept->end(),
              [](const FiredEvent& a, const FiredEvent& b) { return a.time < b.time || (a.time == b.time && a.event < b.event); });
}

}  // namespace crowd
