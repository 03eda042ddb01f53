#pragma once
// What an impostor shows of a character's animation, read from its gpu::CharacterRecord: the C++
// twin of shaders/impostor_pose.glsl.inc (the clip that dominates a crossfade, at the phase both clips
// share). Impostor code reads animation state only through these two functions.
#include <cmath>
#include <cstdint>

#include "gpu_types.h"

namespace render {

struct ImpostorPose {
    std::uint32_t clip = 0;
    float phase = 0.0f;  // in cycles, [0, 1)
};

inline ImpostorPose impostorPose(const gpu::CharacterRecord& character) {
    const std::uint32_t from = character.ids.w & 0xFFFFu;
    const std::uint32_t to = character.ids.w >> 16;
    return {character.pose.y < 0.5f ? from : to, character.pose.x - std::floor(character.pose.x)};
}

}  // namespace render
