#pragma once
// The crowd: every character's own clip, time offset, speed and placement, and the job that turns
// them into bone matrices each frame.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"
#include "model/skinned_model.h"

namespace crowd {

struct Character {
    std::uint32_t clip = 0;
    float timeOffset = 0.0f;  // seconds added to the global time (the character's phase)
    float speed = 1.0f;       // playback rate
    glm::vec3 position{0.0f};
    float heading = 0.0f;     // radians about +y; 0 faces +z
};

struct LayoutOptions {
    std::uint32_t count = 1;
    std::uint32_t seed = 1;
    // Clip every character plays; -1: the model's default clip ("walk" if it has one, else clip 0).
    int clip = -1;
    // Every character picks a random clip (overrides `clip`).
    bool randomClips = false;
};

// Characters on a square grid centred on the origin, facing +z, with seeded jitter of position,
// heading, phase and speed so no two move in lockstep.
std::vector<Character> gridLayout(const model::SkinnedModel& model, const LayoutOptions& options);

// The clip a crowd plays when none is named: "walk" if present, else the first.
std::uint32_t defaultClip(const model::SkinnedModel& model);

// World transform of a character: its heading, then its position.
glm::mat4 characterTransform(const Character& character);

class Crowd {
public:
    Crowd(const model::SkinnedModel& model, std::vector<Character> characters);

    std::uint32_t size() const { return static_cast<std::uint32_t>(characters_.size()); }
    const std::vector<Character>& characters() const { return characters_; }
    const model::SkinnedModel& model() const { return model_; }

    // Writes the skinning matrices of every character at global time `time` (seconds): character c's
    // joint j goes to out[c * boneStride + j]. Work is split over the machine's cores.
    void animate(float time, std::span<gpu::BoneRows> out, std::uint32_t boneStride) const;

    // The skinning matrices of one character (for tests and pose export).
    void animateCharacter(std::uint32_t index, float time, std::span<gpu::BoneRows> out) const;

    // Centre and radius of the ground the crowd stands on.
    glm::vec3 center() const;
    float radius() const;

private:
    const model::SkinnedModel& model_;
    std::vector<Character> characters_;
};

}  // namespace crowd
