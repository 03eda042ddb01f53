#version 460
#extension GL_GOOGLE_include_directive : require
// The event pass, after culling: the clip events that characters in view fire in this frame's window
// (from, to], appended to the event buffer (render/event_pass.h). The GPU half of crowd/events.cpp:
// the same closed form (an event at point p of the cycle fires where the segment's phase reaches
// p + k, solved from the phase curve, not found by stepping) and the same crossfade rule, in float on
// the epoch's clock where the CPU works in double on the scene's.
//
// Two dispatches share this shader: one thread per character over its current segment (counts.z 0),
// then one per character replanned inside the window over the segment it followed before (counts.z
// 1, a table the host uploads), so a replan in the middle of a frame loses no footstep.
#include "gpu_types.h"

layout(local_size_x = CULL_WORKGROUP_SIZE) in;

layout(push_constant) uniform Push { EventPush push; };
layout(std430, set = 0, binding = 0) readonly buffer Models { AnimationModel animModels[]; };
layout(std430, set = 0, binding = 1) readonly buffer Clips { AnimationClip animClips[]; };
layout(std430, set = 0, binding = 2) readonly buffer RootSamples { vec2 rootSamples[]; };
layout(std430, set = 0, binding = 3) readonly buffer Motions { MotionRecord motions[]; };
layout(std430, set = 0, binding = 4) readonly buffer Characters { CharacterRecord characters[]; };
layout(std430, set = 0, binding = 5) readonly buffer ShadowStates { uint shadowStates[]; };
layout(std430, set = 0, binding = 6) readonly buffer ClipEvents { uvec2 clipEvents[]; };  // first, count
layout(std430, set = 0, binding = 7) readonly buffer EventTable { AnimationEvent eventTable[]; };
layout(std430, set = 0, binding = 8) readonly buffer Previous { PreviousSegment previous[]; };
layout(std430, set = 0, binding = 9) readonly buffer Starts { float segmentStarts[]; };
layout(std430, set = 0, binding = 10) buffer Events {
    EventHeader header;
    EventRecord fired[];
};
TERRAIN_BUFFER(0, 11);

#include "motion.glsl.inc"

// A firing time that never comes (below every segment's start).
const float NEVER = -3.0e38;

// The first elapsed time at which the segment's phase meets `target + drift * weight`, or NEVER
// (crowd/events.cpp, PhaseCurve::when): through a crossfade the rate moves linearly from one clip's to
// the other's, so the phase is quadratic there and linear after; a pair of events' point drifts with
// the weight and is met once, at the first meeting. Negative before the record's start: a record
// restated at the epoch (crowd/segment.h: steady, linear) holds back to its segment's true start.
float phaseWhen(MotionRecord m, float target, float drift) {
    float fade = m.timing.y, rateFrom = m.phase.y, rateTo = m.phase.z;
    float d = target - m.phase.x;
    if (fade > 0.0) {
        if (d < 0.0) return NEVER;  // met before this segment
        // a e^2 + b e = d; with d >= 0 its first non-negative root is 2d / (b + sqrt(disc)) if any.
        float a = (rateTo - rateFrom) / (2.0 * fade), b = rateFrom - drift / fade;
        float fadeEnd = motionPhase(m, fade) - drift;
        float disc = b * b + 4.0 * a * d;
        if (target <= fadeEnd) {
            float root = sqrt(max(disc, 0.0));
            return b + root > 0.0 ? 2.0 * d / (b + root) : NEVER;
        }
        if (disc >= 0.0) {
            // Met inside the fade and passed back before its end.
            float root = sqrt(disc);
            if (b + root > 0.0 && 2.0 * d / (b + root) <= fade) return 2.0 * d / (b + root);
        }
        return rateTo > 0.0 ? fade + (target - fadeEnd) / rateTo : NEVER;
    }
    return rateTo > 0.0 ? d / rateTo : NEVER;
}

// The event of clip range `range` whose pair key is `key` (>= 0), or -1.
int partnerIn(uvec2 range, float key) {
    for (uint e = range.x; e < range.x + range.y; ++e)
        if (eventTable[e].moment.w == key) return int(e);
    return -1;
}

#include "terrain_sample.glsl.inc"

// Where the event happens: the character's placement at that moment applied to the joint's position
// in its clip's pose (precomputed per event; the firing clip's pose alone, its weight at least 1/2).
vec3 worldPlace(uint c, MotionRecord m, uint firstClip, float elapsed, vec3 modelPlace) {
    vec3 position = m.origin.xyz;
    if (m.phase.w == MOTION_ROOT) {
        // Before a restated record's start (steady: one clip, no turn) the straight line runs back.
        uint to = firstClip + m.clips.y;
        position.xz += elapsed >= 0.0 ? travelled(m, elapsed, firstClip + m.clips.x, to)
                                      : turnToWorld(rootStep(to, m.phase.x, m.phase.x + m.phase.z * elapsed), m.origin.w);
    }
    position.y += terrainHeightAt(terrainGrid, position.xz);  // on the ground, as the motion pass places it
    float heading = motionHeading(m, elapsed), scale = characters[c].tint.w;
    vec2 turned = turnToWorld(modelPlace.xz * scale, heading);
    return position + vec3(turned.x, modelPlace.y * scale, turned.y);
}

void append(uint c, uint clip, uint event, vec3 place, float age) {
    // Never past the capacity: a slot at or beyond it gives its number back, so count ends at the
    // events written (count only rises while some slot below capacity is unclaimed).
    uint slot = atomicAdd(header.count, 1u);
    if (slot >= header.capacity) {
        atomicAdd(header.count, 0xFFFFFFFFu);
        atomicAdd(header.dropped, 1u);
        return;
    }
    fired[slot] = EventRecord(uvec4(c, clip, event, 0u), vec4(place, age));
}

// The events character c fires following `m` at times t (since the epoch) with from < t <= to and
// begin <= t < end (begin: the segment's true start, at or before the record's).
void fireSegment(uint c, MotionRecord m, float begin, float end) {
    // A driven character's gait and phase come from its keys in the motion pass, not from a record:
    // its events are the CPU's (Crowd::events), this buffer holds the behaviours' (docs/host-driven.md).
    if (m.phase.w >= MOTION_DRIVEN_HOST) return;
    float from = push.window.x, to = push.window.y;
    float lo = max(from, begin), hi = min(to, end);
    if (!(hi >= lo)) return;
    uvec4 model = animModels[characters[c].ids.x].info;
    if (model.w == 0u) return;  // a model without clips fires nothing (and has no row in clipEvents)
    uint firstClip = model.z;
    float start = m.timing.x, fade = m.timing.y;
    float first = motionPhase(m, lo - start), last = motionPhase(m, hi - start);
    uint clipFrom = m.clips.x, clipTo = m.clips.y;
    bool crossfade = clipFrom != clipTo && fade > 0.0;
    uvec2 fromRange = clipEvents[firstClip + clipFrom];
    for (uint i = 0u; i < (clipFrom == clipTo ? 1u : 2u); ++i) {
        uint clip = i == 0u ? clipTo : clipFrom;
        uvec2 range = clipEvents[firstClip + clip];
        for (uint e = range.x; e < range.x + range.y; ++e) {
            AnimationEvent event = eventTable[e];
            // A paired event (crowd/event_pairs.h: equal keys) fires once, from the to-clip's side,
            // where the phase meets the point blended by the weight; others fire from their clip
            // while it weighs more.
            int partner = -1;
            if (crossfade && event.moment.w >= 0.0) {
                if (clip == clipFrom) {
                    if (partnerIn(clipEvents[firstClip + clipTo], event.moment.w) >= 0) continue;
                } else {
                    partner = partnerIn(fromRange, event.moment.w);
                }
            }
            float point = event.moment.x, base = point, drift = 0.0;
            if (partner >= 0) {
                // The from-clip's point within half a cycle of the to-clip's (crowd::blendedPoint).
                float fromPoint = eventTable[partner].moment.x;
                base = fromPoint + floor(point - fromPoint + 0.5);
                drift = point - base;
            }
            // Every meeting of base + k between the window's phases less the point's drift (between 0
            // and drift), one more either side for rounding: the times decide; a window of more than
            // EVENT_MAX_CYCLES cycles keeps its end.
            float kLast = ceil(last - min(drift, 0.0) - base) + 1.0;
            float kFirst = max(floor(first - max(drift, 0.0) - base) - 1.0, kLast - EVENT_MAX_CYCLES);
            for (float k = kFirst; k <= kLast; k += 1.0) {
                float elapsed = phaseWhen(m, base + k, drift);
                float t = start + elapsed;
                if (!(t > from && t <= to && t >= begin && t < end)) continue;
                bool toWins = !(fade > 0.0) || elapsed >= 0.5 * fade;
                if (partner >= 0) {
                    // The pair is reported as the event of the clip that weighs more then, placed
                    // on that clip's pose.
                    uint firing = toWins ? e : uint(partner);
                    append(c, toWins ? clipTo : clipFrom, uint(eventTable[firing].moment.z),
                           worldPlace(c, m, firstClip, elapsed, eventTable[firing].place.xyz), to - t);
                    continue;
                }
                if (clipFrom != clipTo && (clip == clipTo) != toWins) continue;
                append(c, clip, uint(event.moment.z), worldPlace(c, m, firstClip, elapsed, event.place.xyz), to - t);
            }
        }
    }
}

bool inView(uint c) { return (shadowStates[c] & SHADOW_IN_VIEW_BIT) != 0u; }

void main() {
    for (uint i = gl_GlobalInvocationID.x; i < push.counts.x; i += push.counts.y) {
        if (push.counts.z == 0u) {
            if (!inView(i)) continue;
            fireSegment(i, motions[i], segmentStarts[i], 3.0e38);
        } else {
            PreviousSegment p = previous[i];
            if (inView(p.ids.x)) fireSegment(p.ids.x, p.motion, p.span.x, p.span.y);
        }
    }
}
