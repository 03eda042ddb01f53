#pragma once
// How long a model's behaviour episodes last. A milling character's episodes and a formation's march
// cycles start at fixed times, so that the one holding any time is found by a division; each is long
// enough for its slowest trip (or march) and a rest, which then lasts until the next one starts.
#include <cstdint>

#include "anim/clip_library.h"
#include "crowd/gaits.h"

namespace crowd {

struct BehaviourSettings;

struct Rhythm {
    double millEpisode = 0.0;  // seconds: a trip between two targets and the rest after it
    double marchCycle = 0.0;   // seconds: stand, march out, turn about, march back, turn about, halt
    float marchLeg = 0.0f;     // seconds a march out takes, the same for every member of a formation
};

// Zero for a model that cannot travel (its characters stay in place).
Rhythm measureRhythm(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                     const BehaviourSettings& settings);

}  // namespace crowd
