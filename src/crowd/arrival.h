#pragma once
// The last leg of a trip, solved so that the character is exactly at a place at a time. Root motion
// carries a character along its clips' own sway and stride, so aiming at a place lands near it, not on
// it; a behaviour that hands over to a closed-form state (crowd/mill.h, crowd/march.h) must land on it,
// or the next episode would start a few centimetres off. So the leg's heading and length are found by
// Newton's method on the closed form of the leg and of what follows it (a stop, a turn about), until
// the character is within kArrivalTolerance of the place.
//
// A character that stands by holding its walk still (crowd/standing.h) cannot be solved so: its stop
// must end at a given phase of the walk, and a walk covers one stride a cycle, so the phase fixes how
// far it goes and the leg's length no longer moves where it arrives. Its way is bent instead: two legs
// whose lengths the phase budget gives, their headings solved.
#include <functional>

#include "crowd/behaviours.h"

namespace crowd {

// Metres: well under a pixel at any distance a character is drawn as a mesh.
inline constexpr float kArrivalTolerance = 1e-4f;

// How a leg starts: a transition from the current segment into `gait` at `rate`, over `fade`.
struct LegStart {
    double at = 0.0;
    std::uint32_t gait = 0;
    float rate = 1.0f;
    float fade = 0.0f;
};

// The leg: the transition, turning by `angle` at the turn rate, sealed. The solves work on the angle,
// not on the heading turned to: a turn the shorter way would jump from one way round to the other
// as the heading passes behind the character.
Segment legTurningBy(const Segment& current, const LegStart& start, float angle, const PlanContext& context);

// What follows a leg ending at `legEnd`: the segment that holds the arrival time (built from the leg
// by the same steps the behaviour takes later, so the solve sees exactly what will be played).
using ArrivalTail = std::function<Segment(const Segment& leg, double legEnd)>;

struct Arrival {
    Segment leg;          // turning by the solved angle, sealed
    double legEnd = 0.0;  // when the tail takes over
    float miss = 0.0f;    // metres between where it arrives and `place`
};

// The leg from `current` that, followed by `tail`, puts the character at `place` at `when`.
Arrival arrive(const Segment& current, const LegStart& start, glm::vec2 place, double when, const ArrivalTail& tail,
               const PlanContext& context);

struct BentArrival {
    Segment first;             // turning by the first solved angle, sealed
    double firstEnd = 0.0;     // when the second leg starts: legTurningBy(first, {firstEnd, gait, rate, 0}, ...)
    float secondTurn = 0.0f;   // radians it turns by
    double secondLength = 0.0; // seconds of the second leg: the tail takes over at firstEnd + secondLength
    float miss = 0.0f;
};

// Two legs from `current` lasting `length` seconds in all (the second in the same gait and rate,
// without a fade), bent so that, followed by `tail` (which goes on about `tailReach` metres), they put
// the character at `place` at `when`. They are split so that each covers about half the way; the tail
// is first called with the split made (a tail may fix choices then, counted from its leg's phase).
BentArrival arriveBent(const Segment& current, const LegStart& start, double length, float tailReach, glm::vec2 place,
                       double when, const ArrivalTail& tail, const PlanContext& context);

}  // namespace crowd
