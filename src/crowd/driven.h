#pragma once
// Characters the host drives with its own samples (docs/host-driven.md): the settings, each model's
// gaits, and the keys the CPU makes of samples from the host's memory (shaders/driven_keys.h says how).
// A character is driven by the host's arrays (its keys made here, uploaded as they come) or by a device
// buffer the host's own pass fills (its keys made on the GPU, which the CPU never sees).
#include <cstdint>
#include <span>
#include <vector>

#include "anim/clip_library.h"
#include "crowd/gaits.h"
#include "gpu_types.h"

namespace crowd {

enum class Driven : std::uint8_t { No, HostSamples, DeviceSamples };

// Crowd-wide: how far behind its samples a driven character is drawn, and how long it goes on past its
// last sample before it comes to rest.
struct DrivenTiming {
    double delay = 0.1;        // seconds (an interpolation buffer: cover the samples' interval and jitter)
    double extrapolate = 0.5;  // seconds
};

// A model's gaits for driven characters (the host may set them; crowdgpu::GaitSettings).
struct GaitBands {
    float walkFrom = 0.0f;   // m/s: slower stands
    float runFrom = 0.0f;    // m/s: faster runs
    float hysteresis = 0.1f; // a fraction of a band's edge a gait stays in past it
    float fade = 0.3f;       // seconds a whole gait change takes
    float turnRate = 4.0f;   // rad/s the body turns at most
    float turnSpeed = 0.05f; // m/s: slower motion does not turn the body
};

// The bands a model starts with: walking from a tenth of its walk's natural speed, running from half
// way between its walk's and its run's natural speeds (past three times the walk's without a run).
GaitBands defaultGaitBands(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits);
// The GPU table entry of a model's gaits and bands (its clips, strides and rates measured here).
gpu::DrivenModel drivenModel(const anim::ClipLibrary& library, std::uint32_t model, const Gaits& gaits,
                             const GaitBands& bands);

// One sample of the host's, for one slot.
struct DrivenSample {
    std::uint32_t slot;
    double time;    // scene seconds
    float x, z;     // world metres on the ground
    float heading;  // radians about +y; NaN: towards the motion
};

// The keys of the characters driven from the host's memory: per slot a ring of its last `perSlot`. Kept as
// the GPU keeps them, ring entry k of every slot together (k x slots + slot): a batch that gives each
// character its next sample reads and writes the keys in one sweep rather than a cache line a character.
class DrivenKeys {
public:
    DrivenKeys() = default;
    DrivenKeys(std::uint32_t slots, std::uint32_t perSlot);
    std::uint32_t perSlot() const { return perSlot_; }
    bool empty() const { return keys_.empty(); }
    // Keys the slot has had since it was last cleared (the ring holds the last perSlot of them).
    std::uint32_t count(std::uint32_t slot) const { return counts_[slot]; }
    // Key `index` (counted from the slot's first; one the ring still holds).
    const gpu::DrivenKey& key(std::uint32_t slot, std::uint32_t index) const { return keys_[at(slot, index)]; }
    void push(std::uint32_t slot, const gpu::DrivenKey& key) { keys_[at(slot, counts_[slot]++)] = key; }
    void clear(std::uint32_t slot) { counts_[slot] = 0; }
    // The oldest key the ring still holds.
    std::uint32_t oldest(std::uint32_t slot) const { return counts_[slot] > perSlot_ ? counts_[slot] - perSlot_ : 0u; }

private:
    std::size_t at(std::uint32_t slot, std::uint32_t index) const {
        return std::size_t{index % perSlot_} * counts_.size() + slot;
    }
    std::uint32_t perSlot_ = 0;
    std::vector<gpu::DrivenKey> keys_;
    std::vector<std::uint32_t> counts_;
};

// A key's time on the scene clock.
double keySceneTime(const gpu::DrivenKey& key);

}  // namespace crowd
