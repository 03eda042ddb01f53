// Characters the host drives: the rules that turn its samples into keys and keys into a pose, written
// once for C++ and GLSL (docs/host-driven.md). C++ includes this inside a namespace that has glm's
// functions and gpu_types.h's types (crowd/driven_rules.h); GLSL includes it after gpu_types.h.
//
// A sample is where the host's agent was at a time (a position on the ground, and optionally which way it
// faces). Each sample becomes a key when it arrives, from the key before it: the gait and the phase the
// character has reached there, and which way its body faces. Between two keys everything is linear in
// time (position, phase, gait, heading), so the feet move at the ground speed on every stretch and any
// time's pose is a few operations away: the renderer draws each character at the frame's time less the
// host's delay, between the keys around it, as a network game's interpolation buffer does.
//
// Gaits: 0 stands, 1 walks, 2 runs; a gait between two of them is their crossfade, both clips at the
// same phase. The gait a stretch aims for comes from its speed (DrivenModel::bands, with hysteresis), and
// the gait moves towards it by at most one step per bands.w seconds. The phase advances at the rate that
// carries the clips' stride at the ground speed (the standing clip at its own rate); the body turns
// towards the motion (or the heading the sample gives) at most turning.x radians a second.
#ifndef CROWD_DRIVEN_KEYS_H
#define CROWD_DRIVEN_KEYS_H

// C++ defines these functions in every file that includes them: inline there.
#ifdef __cplusplus
#define DRIVEN_FN inline
#else
#define DRIVEN_FN
#endif

#define DRIVEN_PI 3.14159265358979f
// A first key's gait (DrivenKey::motion.z): none yet.
#define DRIVEN_GAIT_UNKNOWN -1.0f

// An angle brought into [-pi, pi).
DRIVEN_FN float drivenWrap(float angle) {
    return angle - 2.0f * DRIVEN_PI * floor((angle + DRIVEN_PI) / (2.0f * DRIVEN_PI));
}

// `from` moved towards `to` by at most `most`.
DRIVEN_FN float drivenApproach(float from, float to, float most) { return from + clamp(to - from, -most, most); }

// The gait a stretch at `speed` aims for, from the model's bands, staying in the gait it is in (the
// nearest whole one to `gait`) while the speed is within the hysteresis of the band's edge.
DRIVEN_FN float drivenTargetGait(float speed, float gait, DrivenModel model) {
    float current = floor(gait + 0.5f);
    float walkFrom = model.bands.x, runFrom = model.bands.y, h = model.bands.z;
    float standBelow = current >= 1.0f ? walkFrom * (1.0f - h) : walkFrom * (1.0f + h);
    float runAbove = current >= 2.0f ? runFrom * (1.0f - h) : runFrom * (1.0f + h);
    return speed < standBelow ? 0.0f : (speed < runAbove ? 1.0f : 2.0f);
}

// Cycles per second of gait `gait` at the ground speed `speed`: a travelling clip's stride carried at
// that speed, the standing clip at its own rate, a crossfade the blend of its two.
DRIVEN_FN float drivenCyclesPerSecond(float gait, float speed, DrivenModel model) {
    float level = min(floor(gait), 1.0f);
    float w = gait - level;
    float walk = model.cycles.y > 0.0f ? speed / model.cycles.y : model.cycles.w;
    float run = model.cycles.z > 0.0f ? speed / model.cycles.z : walk;
    float lower = level < 1.0f ? model.cycles.x : walk;
    float upper = level < 1.0f ? walk : run;
    return mix(lower, upper, w);
}

// Where a key is on the ground (x, z). (No swizzles here: C++ has none.)
DRIVEN_FN vec2 drivenGround(DrivenKey key) { return vec2(key.place.y, key.place.z); }

// A key's time on the clock of epoch `epoch` (seconds since it; crowd/epoch.h: the epochs are whole
// multiples of EPOCH_SECONDS apart, so the sum is exact).
DRIVEN_FN float drivenKeyTime(DrivenKey key, float epoch) { return key.place.x + (key.motion.w - epoch) * EPOCH_SECONDS; }

// The key of a sample at `time` (on the clock of epoch `epoch`) at (x, z), facing `heading` when it is a
// number (NaN: towards the motion), after `previous` (whose time is before it); `first`: there is none.
DRIVEN_FN DrivenKey drivenKeyAfter(DrivenKey previous, bool first, float time, float epoch, vec2 position, float heading,
                         DrivenModel model) {
    DrivenKey key;
    key.place = vec4(time, position.x, position.y, 0.0f);
    key.motion = vec4(0.0f, 0.0f, 0.0f, epoch);
    if (first) {
        // Its gait is not known before a second sample gives a speed: the next key takes the gait its
        // stretch's speed asks for at once (a character that appears walking does not fade in from standing).
        key.place.w = isnan(heading) ? 0.0f : drivenWrap(heading);
        key.motion.z = DRIVEN_GAIT_UNKNOWN;
        return key;
    }
    float dt = time - drivenKeyTime(previous, epoch);
    vec2 step = position - drivenGround(previous);
    float distance = length(step);
    float speed = dt > 0.0f ? distance / dt : 0.0f;
    bool known = previous.motion.z >= 0.0f;
    float target = drivenTargetGait(speed, known ? previous.motion.z : 1.0f, model);
    float gait = known ? drivenApproach(previous.motion.z, target, model.bands.w > 0.0f ? dt / model.bands.w : 2.0f) : target;
    // The rate at the stretch's middle: its gait moves linearly across it.
    float cycles = drivenCyclesPerSecond(known ? 0.5f * (previous.motion.z + gait) : gait, speed, model) * dt;
    float towards = !isnan(heading) ? heading : (speed > model.turning.y ? atan(step.x, step.y) : previous.place.w);
    float turn = drivenWrap(towards - previous.place.w);
    key.place.w = drivenWrap(previous.place.w + clamp(turn, -model.turning.x * dt, model.turning.x * dt));
    key.motion.x = fract(previous.motion.x + cycles);
    key.motion.y = cycles;
    key.motion.z = gait;
    return key;
}

// Where a driven character is and what it plays.
struct DrivenPose {
    vec2 position;  // x, z
    float heading;
    float phase;    // cycles (its fraction is the point in the cycle)
    float gait;     // 0 stand .. 2 run
};

// The pose at `time` between keys `a` and `b` (times ta < tb on one clock; time clamped between them).
DRIVEN_FN DrivenPose drivenBetween(DrivenKey a, DrivenKey b, float ta, float tb, float time) {
    float u = tb > ta ? clamp((time - ta) / (tb - ta), 0.0f, 1.0f) : 1.0f;
    DrivenPose pose;
    pose.position = mix(drivenGround(a), drivenGround(b), u);
    pose.heading = drivenWrap(a.place.w + u * drivenWrap(b.place.w - a.place.w));
    pose.phase = a.motion.x + u * b.motion.y;
    // From a first key (its gait unknown), the second's gait throughout.
    pose.gait = mix(a.motion.z >= 0.0f ? a.motion.z : b.motion.z, b.motion.z, u);
    return pose;
}

// The lower of the two gaits a crossfade at `gait` blends (0 or 1), and their clips: the lower's, then
// the upper's, whose weight is gait less the level.
DRIVEN_FN float drivenLevel(float gait) { return min(floor(gait), 1.0f); }
DRIVEN_FN uvec2 drivenClips(float gait, DrivenModel model) {
    return drivenLevel(gait) < 1.0f ? uvec2(model.clips.x, model.clips.y) : uvec2(model.clips.y, model.clips.z);
}

// The pose at a key.
DRIVEN_FN DrivenPose drivenAt(DrivenKey key) {
    DrivenPose pose;
    pose.position = drivenGround(key);
    pose.heading = key.place.w;
    pose.phase = key.motion.x;
    pose.gait = max(key.motion.z, 0.0f);  // a first key alone: standing
    return pose;
}

// Past the newest key (`last`, at time tl; `previous` before it at tp, unless `only`): the character goes
// on at the last stretch's velocity for `extrapolate` seconds, then comes to rest over two gait changes,
// then stands, playing its standing gait. Each is a key made as a sample would make it.
DRIVEN_FN DrivenPose drivenBeyond(DrivenKey previous, DrivenKey last, bool only, float tp, float tl, float time,
                        float extrapolate, float epoch, DrivenModel model) {
    vec2 velocity = !only && tl > tp ? (drivenGround(last) - drivenGround(previous)) / (tl - tp) : vec2(0.0f);
    float heading = last.place.w;  // the body keeps facing where it faced: turning needs a motion to follow
    float te = tl + extrapolate;
    DrivenKey onward = drivenKeyAfter(last, false, te, epoch, drivenGround(last) + velocity * extrapolate, heading, model);
    if (time <= te) return drivenBetween(last, onward, tl, te, time);
    float rest = 2.0f * max(model.bands.w, 0.0f);
    DrivenKey still = drivenKeyAfter(onward, false, te + rest, epoch, drivenGround(onward), heading, model);
    if (time <= te + rest) return drivenBetween(onward, still, te, te + rest, time);
    DrivenPose pose = drivenAt(still);
    pose.phase += (time - te - rest) * drivenCyclesPerSecond(still.motion.z, 0.0f, model);
    return pose;
}

#endif
