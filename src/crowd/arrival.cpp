#include "crowd/arrival.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "crowd/plan_steps.h"

namespace crowd {
namespace {

constexpr int kMostIterations = 16;
constexpr float kHeadingStep = 1e-3f;  // radians: finite differences of the Jacobians
constexpr double kLengthStep = 1e-3;   // seconds
constexpr double kLargestHeadingChange = 0.5;
constexpr double kLargestLengthChange = 2.0;

// Solves [a b] x = r for 2-vectors a and b; false when they are (almost) parallel.
bool solve2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 r, glm::dvec2& x) {
    const double det = a.x * b.y - b.x * a.y;
    if (!(std::abs(det) > 1e-12)) return false;
    x = {(r.x * b.y - b.x * r.y) / det, (a.x * r.y - r.x * a.y) / det};
    return true;
}

// Scales a Newton step down to at most `largest` per unknown: far from the answer the closed form is
// anything but linear.
glm::dvec2 damped(glm::dvec2 step, glm::dvec2 largest) {
    const double scale = std::min({1.0, largest.x / std::max(std::abs(step.x), 1e-12),
                                   largest.y / std::max(std::abs(step.y), 1e-12)});
    return step * scale;
}

glm::vec2 arrivesAt(const Segment& last, double when, const PlanContext& context) {
    return groundOf(stateOf(last, when, context.library, context.model));
}

// Newton's method on two unknowns: `at(x)` is where the character arrives. The Jacobian comes from
// finite differences of `steps` at the first guess and is then kept up to date by Broyden's rule from
// each step taken: one evaluation per iteration instead of three (each is a few quadratures, and a
// milling crowd of 1,000,000 solves about 10,000 arrivals a frame). Should the update stop helping
// (a step that misses more than the last), the Jacobian is measured again. Returns the best x seen
// and its miss.
template <typename Arrives>
glm::dvec2 newton(glm::dvec2 x, glm::dvec2 steps, glm::dvec2 largest, glm::vec2 place, const Arrives& at, float& miss) {
    glm::dvec2 best = x;
    miss = std::numeric_limits<float>::infinity();
    glm::dvec2 byFirst(0.0), bySecond(0.0);  // the Jacobian's columns
    bool measured = false;
    glm::vec2 here = at(x);
    float lastOff = std::numeric_limits<float>::infinity();
    for (int iteration = 0; iteration < kMostIterations; ++iteration) {
        const float off = glm::distance(here, place);
        if (off < miss) miss = off, best = x;
        if (off < kArrivalTolerance) break;
        if (!measured || off >= lastOff) {
            byFirst = glm::dvec2(at(x + glm::dvec2(steps.x, 0.0)) - here) / steps.x;
            bySecond = glm::dvec2(at(x + glm::dvec2(0.0, steps.y)) - here) / steps.y;
            measured = true;
        }
        lastOff = off;
        glm::dvec2 step;
        if (!solve2(byFirst, bySecond, glm::dvec2(place - here), step)) break;
        step = damped(step, largest);
        x += step;
        const glm::vec2 next = at(x);
        // Broyden: J += (df - J dx) dx^T / (dx . dx), so that J dx = df for the step just taken.
        const glm::dvec2 df = glm::dvec2(next - here);
        const glm::dvec2 predicted = byFirst * step.x + bySecond * step.y;
        const double length2 = glm::dot(step, step);
        if (length2 > 0.0) {
            const glm::dvec2 correction = (df - predicted) / length2;
            byFirst += correction * step.x;
            bySecond += correction * step.y;
        }
        here = next;
    }
    if (kMostIterations > 0) {
        const float off = glm::distance(here, place);
        if (off < miss) miss = off, best = x;
    }
    return best;
}

}  // namespace

Segment legTurningBy(const Segment& current, const LegStart& start, float angle, const PlanContext& context) {
    Segment leg = transition(current, start.at, start.gait, start.rate, start.fade, context);
    turnBy(leg.motion, angle, kTurnRate);
    seal(leg, context.library, context.model);
    return leg;
}

Arrival arrive(const Segment& current, const LegStart& start, glm::vec2 place, double when, const ArrivalTail& tail,
               const PlanContext& context) {
    const MotionState then = stateOf(current, start.at, context.library, context.model);
    const glm::vec2 from = groundOf(then);
    // First guess: straight at the place, for as long as the gait takes to cover the way.
    const float speed = glm::length(context.library.stride(context.model, start.gait)) *
                        cyclesPerSecond(context.library, context.model, start.gait, start.rate);
    const glm::dvec2 guess(wrapAngle(headingTowards(from, place, start.gait, context) - then.heading),
                           speed > 0.0f ? glm::distance(from, place) / speed : 0.0);
    // The leg must finish its crossfade before the tail starts: a tail fades from one clip only.
    const double shortest = start.fade;
    auto at = [&](glm::dvec2 x) {
        const Segment leg = legTurningBy(current, start, static_cast<float>(x.x), context);
        return arrivesAt(tail(leg, start.at + std::max(x.y, shortest)), when, context);
    };
    Arrival arrival;
    const glm::dvec2 x = newton(guess, {kHeadingStep, kLengthStep}, {kLargestHeadingChange, kLargestLengthChange},
                                place, at, arrival.miss);
    arrival.leg = legTurningBy(current, start, static_cast<float>(x.x), context);
    arrival.legEnd = start.at + std::max(x.y, shortest);
    return arrival;
}

BentArrival arriveBent(const Segment& current, const LegStart& start, double length, float tailReach, glm::vec2 place,
                       double when, const ArrivalTail& tail, const PlanContext& context) {
    const MotionState then = stateOf(current, start.at, context.library, context.model);
    const glm::vec2 from = groundOf(then);
    const float straight = wrapAngle(headingTowards(from, place, start.gait, context) - then.heading);
    // The split: the first leg covers half of what the two legs and the tail cover in a straight line.
    const Segment straightFirst = legTurningBy(current, start, straight, context);
    const glm::vec2 legsEnd = groundOf(stateOf(straightFirst, start.at + length, context.library, context.model));
    const float reach = glm::distance(legsEnd, from) + tailReach;
    const double firstLength = std::clamp<double>(timeToCover(straightFirst, 0.5f * reach, context), start.fade, length);
    const double firstEnd = start.at + firstLength, secondLength = length - firstLength;
    auto at = [&](glm::dvec2 x) {
        const Segment first = legTurningBy(current, start, static_cast<float>(x.x), context);
        const Segment second = legTurningBy(first, {firstEnd, start.gait, start.rate, 0.0f}, static_cast<float>(x.y), context);
        return arrivesAt(tail(second, firstEnd + secondLength), when, context);
    };
    // First guess: an isosceles triangle on the way there, its sides half the straight reach, bent to the
    // side that turns least from where the character faces.
    const double side = 0.5 * reach, base = std::max<double>(glm::distance(from, place), 1e-3);
    const float corner = static_cast<float>(std::acos(std::clamp(0.5 * base / side, -1.0, 1.0)));
    const float firstTurn = straight + (straight >= 0.0f ? -corner : corner);
    const glm::vec2 stride = context.library.stride(context.model, start.gait);
    const glm::vec2 cornerAt = from + static_cast<float>(side) * glm::normalize(turnToWorld(stride, then.heading + firstTurn));
    const float secondTurn =
        wrapAngle(headingTowards(cornerAt, place, start.gait, context) - (then.heading + firstTurn));
    BentArrival arrival;
    const glm::dvec2 x = newton(glm::dvec2(firstTurn, secondTurn), {kHeadingStep, kHeadingStep},
                                {kLargestHeadingChange, kLargestHeadingChange}, place, at, arrival.miss);
    arrival.first = legTurningBy(current, start, static_cast<float>(x.x), context);
    arrival.firstEnd = firstEnd;
    arrival.secondTurn = static_cast<float>(x.y);
    arrival.secondLength = secondLength;
    return arrival;
}

}  // namespace crowd
