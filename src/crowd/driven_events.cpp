#include "crowd/driven_events.h"

#include <algorithm>
#include <cmath>

#include "crowd/driven_rules.h"
#include "crowd/epoch.h"
#include "crowd/event_pairs.h"

namespace crowd {
namespace {

// One stretch between two keys, on the scene clock: phase and gait linear from its start to its end.
struct Stretch {
    double start, end;    // scene seconds (the keys' times plus the delay)
    double phase, cycles; // the phase at the start (cycles) and how many it advances by the end
    double gaitStart, gaitEnd;
};

struct EventContext {
    const model::SkinnedModel& model;
    const anim::ClipLibrary& library;
    std::uint32_t modelIndex;
    const gpu::DrivenModel& driven;
    std::uint32_t slot;
    double from, to;
    std::vector<FiredEvent>& out;
};

// The events of a part of a stretch, u in [u0, u1] (fractions of it), whose gait stays within one pair
// of gaits: `level`'s clips, the upper weighing gait - level.
void partEvents(const Stretch& s, double u0, double u1, std::uint32_t level, const EventContext& c) {
    const std::uint32_t clipFrom = level == 0 ? c.driven.clips.x : c.driven.clips.y;
    const std::uint32_t clipTo = level == 0 ? c.driven.clips.y : c.driven.clips.z;
    if (!(s.cycles > 0.0) || c.model.clips.empty()) return;
    const double wa = s.gaitStart - level, dw = s.gaitEnd - s.gaitStart;  // weight of clipTo: wa + dw u
    auto timeAt = [&](double u) { return s.start + u * (s.end - s.start); };
    auto weightAt = [&](double u) { return wa + dw * u; };
    const float fromDuration = c.library.duration(c.modelIndex, clipFrom), toDuration = c.library.duration(c.modelIndex, clipTo);
    const bool pairing = clipFrom != clipTo && !c.model.clips[clipFrom].events.empty() &&
                         !c.model.clips[clipTo].events.empty() && fromDuration > 0.0f && toDuration > 0.0f;
    const std::uint32_t clips[2] = {clipTo, clipFrom};
    for (std::uint32_t i = 0; i < (clipFrom == clipTo ? 1u : 2u); ++i) {
        const std::uint32_t clip = clips[i];
        const anim::Clip& anim = c.model.clips[clip];
        const float duration = c.library.duration(c.modelIndex, clip);
        if (!(duration > 0.0f)) continue;
        for (std::uint32_t e = 0; e < anim.events.size(); ++e) {
            std::int32_t partner = -1;
            if (pairing) {
                if (clip == clipFrom && hasPartner(anim, e, c.model.clips[clipTo])) continue;
                if (clip == clipTo) partner = pairedEvent(c.model.clips[clipFrom], anim, e);
            }
            const double point = static_cast<double>(anim.events[e].time) / duration;
            const BlendedPoint blend =
                partner >= 0 ? blendedPoint(static_cast<double>(c.model.clips[clipFrom].events[partner].time) / fromDuration, point)
                             : BlendedPoint{point, 0.0};
            // phase(u) - drift weight(u) = base + k, linear in u: one meeting per k.
            const double slope = s.cycles - blend.drift * dw;
            if (!(slope > 0.0)) continue;
            const double lo = s.phase + s.cycles * u0 - blend.drift * weightAt(u0) - blend.base;
            const double hi = s.phase + s.cycles * u1 - blend.drift * weightAt(u1) - blend.base;
            for (double k = std::ceil(lo) - 1.0; k <= std::floor(hi) + 1.0; k += 1.0) {
                const double u = (blend.base + k - s.phase + blend.drift * wa) / slope;
                if (!(u > u0 && u <= u1)) continue;
                const double t = timeAt(u);
                if (!(t > c.from && t <= c.to)) continue;
                const bool toWins = weightAt(u) >= 0.5;
                if (partner >= 0) {
                    c.out.push_back(toWins ? FiredEvent{c.slot, clipTo, e, t}
                                           : FiredEvent{c.slot, clipFrom, static_cast<std::uint32_t>(partner), t});
                    continue;
                }
                if (clipFrom != clipTo && (clip == clipTo) != toWins) continue;
                c.out.push_back({c.slot, clip, e, t});
            }
        }
    }
}

// A stretch's events, its parts split where its gait crosses from one pair of gaits to the next.
void stretchEvents(const Stretch& s, const EventContext& c) {
    if (!(s.end > c.from) || !(s.start < c.to)) return;
    double u0 = 0.0;
    const double ga = s.gaitStart, gb = s.gaitEnd;
    // The crossing of gait 1 (stand-walk to walk-run), if the stretch has one.
    if ((ga < 1.0 && gb > 1.0) || (ga > 1.0 && gb < 1.0)) {
        const double u = (1.0 - ga) / (gb - ga);
        partEvents(s, 0.0, u, ga < 1.0 ? 0u : 1u, c);
        u0 = u;
    }
    const double gMiddle = ga + (gb - ga) * 0.5 * (u0 + 1.0);
    partEvents(s, u0, 1.0, static_cast<std::uint32_t>(std::min(std::floor(gMiddle), 1.0)), c);
}

Stretch stretchOf(const gpu::DrivenKey& a, const gpu::DrivenKey& b, double delay) {
    // From a first key (its gait unknown: DRIVEN_GAIT_UNKNOWN), the second one's gait throughout.
    return {keySceneTime(a) + delay, keySceneTime(b) + delay, a.motion.x, b.motion.y,
            a.motion.z >= 0.0f ? a.motion.z : b.motion.z, b.motion.z};
}

}  // namespace

void drivenEvents(const DrivenKeys& keys, std::uint32_t slot, const model::SkinnedModel& model,
                  const anim::ClipLibrary& library, std::uint32_t modelIndex, const gpu::DrivenModel& driven,
                  const DrivenTiming& timing, double from, double to, std::vector<FiredEvent>& out) {
    const std::uint32_t count = keys.count(slot);
    if (count == 0 || !(to > from)) return;
    const std::size_t mark = out.size();
    const EventContext c{model, library, modelIndex, driven, slot, from, to, out};
    for (std::uint32_t k = keys.oldest(slot); k + 1 < count; ++k)
        stretchEvents(stretchOf(keys.key(slot, k), keys.key(slot, k + 1), timing.delay), c);
    // Past the newest key: on at the last velocity, to rest, then standing (drivenBeyond's keys).
    const gpu::DrivenKey& last = keys.key(slot, count - 1);
    const double lastTime = keySceneTime(last) + timing.delay;
    if (to > lastTime) {
        const bool only = count - 1 == keys.oldest(slot);
        const gpu::DrivenKey& previous = keys.key(slot, only ? count - 1 : count - 2);
        const auto epoch = last.motion.w;
        const float tl = last.place.x, tp = driven::drivenKeyTime(previous, epoch);
        const glm::vec2 velocity = !only && tl > tp ? (glm::vec2(last.place.y, last.place.z) - glm::vec2(previous.place.y, previous.place.z)) / (tl - tp)
                                                    : glm::vec2(0.0f);
        const auto extrapolate = static_cast<float>(timing.extrapolate);
        const float te = tl + extrapolate, rest = 2.0f * std::max(driven.bands.w, 0.0f);
        const gpu::DrivenKey onward = driven::drivenKeyAfter(last, false, te, epoch, glm::vec2(last.place.y, last.place.z) + velocity * extrapolate,
                                                             last.place.w, driven);
        const gpu::DrivenKey still = driven::drivenKeyAfter(onward, false, te + rest, epoch, glm::vec2(onward.place.y, onward.place.z),
                                                            last.place.w, driven);
        stretchEvents(stretchOf(last, onward, timing.delay), c);
        stretchEvents(stretchOf(onward, still, timing.delay), c);
        const double standStart = keySceneTime(still) + timing.delay;
        if (to > standStart) {
            const double rate = driven::drivenCyclesPerSecond(still.motion.z, 0.0f, driven);
            stretchEvents({standStart, to, still.motion.x, rate * (to - standStart), still.motion.z, still.motion.z}, c);
        }
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(mark), out.end(),
              [](const FiredEvent& a, const FiredEvent& b) { return a.time < b.time || (a.time == b.time && a.event < b.event); });
}

}  // namespace crowd
