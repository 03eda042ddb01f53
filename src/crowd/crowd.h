#pragma once
// The crowd: every character's model, clip, time offset, speed and placement, and the job that turns
// them into bone matrices each frame. A crowd may mix models (soldiers beside horses beside glTF
// characters); a character names its model by index into the crowd's model list.
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
    std::uint32_t model = 0;  // index into the crowd's models
    float scale = 1.0f;       // uniform scale of the model
    glm::vec3 tint{1.0f};     // colour multiplier, so a crowd of one model does not look cloned
};

struct LayoutOptions {
    std::uint32_t count = 1;
    std::uint32_t seed = 1;
    // Per model: the clip its characters play; -1 (or a missing entry): the model's default clip.
    std::vector<int> clips;
    // Every character picks a random clip of its model (overrides `clips`).
    bool randomClips = false;
    // Per model: its share of the crowd (relative weights); empty: equal shares.
    std::vector<float> weights;
    // Per model: uniform scale of its characters; empty: 1.
    std::vector<float> scales;
};

// Characters on a square grid centred on the origin, facing +z, with seeded jitter of position,
// heading, phase and speed so no two move in lockstep, a seeded brightness tint, and models drawn
// by weight. The grid's spacing fits the widest model, so neighbours never intersect.
std::vector<Character> gridLayout(std::span<const model::SkinnedModel* const> models, const LayoutOptions& options);

// The clip a crowd plays when none is named: "walk" if present, else the first.
std::uint32_t defaultClip(const model::SkinnedModel& model);

// The brightness variation of character `index` of a grid (0.82 to 1.18, a hash of the index).
float brightnessVariation(std::uint32_t index);

// World transform of a character: its scale, then its heading, then its position.
glm::mat4 characterTransform(const Character& character);

class Crowd {
public:
    // The models must outlive the crowd. Throws gpu::Error when a character names a model or clip
    // that does not exist, or when there are more than MAX_MODELS models.
    Crowd(std::vector<const model::SkinnedModel*> models, std::vector<Character> characters);
    // A crowd of one model.
    Crowd(const model::SkinnedModel& model, std::vector<Character> characters);

    std::uint32_t size() const { return static_cast<std::uint32_t>(characters_.size()); }
    const std::vector<Character>& characters() const { return characters_; }
    const std::vector<const model::SkinnedModel*>& models() const { return models_; }
    const model::SkinnedModel& model(std::uint32_t index) const { return *models_[index]; }
    const model::SkinnedModel& modelOf(std::uint32_t character) const { return *models_[characters_[character].model]; }

    // Writes the skinning matrices of every character at global time `time` (seconds): character c's
    // joint j goes to out[boneOffsets[c] + j]. Work is split over the machine's cores.
    void animate(float time, std::span<gpu::BoneRows> out, std::span<const std::uint32_t> boneOffsets) const;

    // The skinning matrices of one character (for tests and pose export).
    void animateCharacter(std::uint32_t index, float time, std::span<gpu::BoneRows> out) const;

    // Centre and radius of the ground the crowd stands on, and its tallest model's height.
    glm::vec3 center() const;
    float radius() const;
    float tallestHeight() const;

private:
    std::vector<const model::SkinnedModel*> models_;
    std::vector<Character> characters_;
};

}  // namespace crowd
