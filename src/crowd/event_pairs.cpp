#include "crowd/event_pairs.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace crowd {
namespace {

bool sameKind(const anim::ClipEvent& a, const anim::ClipEvent& b) { return a.joint == b.joint && a.name == b.name; }

// The index of the only event of `clip` of `event`'s name and joint, -1 if none, -2 if several.
std::int32_t onlyOfKind(const anim::Clip& clip, const anim::ClipEvent& event) {
    std::int32_t found = -1;
    for (std::uint32_t e = 0; e < clip.events.size(); ++e) {
        if (!sameKind(clip.events[e], event)) continue;
        if (found != -1) return -2;
        found = static_cast<std::int32_t>(e);
    }
    return found;
}

}  // namespace

std::int32_t pairedEvent(const anim::Clip& from, const anim::Clip& to, std::uint32_t toEvent) {
    if (onlyOfKind(to, to.events[toEvent]) != static_cast<std::int32_t>(toEvent)) return -1;
    const std::int32_t partner = onlyOfKind(from, to.events[toEvent]);
    return partner >= 0 ? partner : -1;
}

bool hasPartner(const anim::Clip& from, std::uint32_t fromEvent, const anim::Clip& to) {
    if (onlyOfKind(from, from.events[fromEvent]) != static_cast<std::int32_t>(fromEvent)) return false;
    return onlyOfKind(to, from.events[fromEvent]) >= 0;
}

std::vector<std::vector<std::int32_t>> eventPairKeys(const std::vector<anim::Clip>& clips) {
    std::map<std::pair<std::string, std::int32_t>, std::int32_t> keys;
    std::vector<std::vector<std::int32_t>> result(clips.size());
    for (std::size_t c = 0; c < clips.size(); ++c) {
        for (std::uint32_t e = 0; e < clips[c].events.size(); ++e) {
            const anim::ClipEvent& event = clips[c].events[e];
            std::int32_t key = -1;
            if (onlyOfKind(clips[c], event) == static_cast<std::int32_t>(e))
                key = keys.try_emplace({event.name, event.joint}, static_cast<std::int32_t>(keys.size())).first->second;
            result[c].push_back(key);
        }
    }
    return result;
}

BlendedPoint blendedPoint(double fromPoint, double toPoint) {
    // The from-clip's point shifted by whole cycles to within half a cycle of the to-clip's: the two
    // feet's touchdowns closest in the cycle are the one step.
    // floor(x + 0.5), as the event pass does, so both break a tie of exactly half a cycle alike.
    const double base = fromPoint + std::floor(toPoint - fromPoint + 0.5);
    return {base, toPoint - base};
}

}  // namespace crowd
